<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="sv_SE">
<context>
    <name>GlSupport</name>
    <message>
        <source>OpenGL 3.2 is not available, so the 3D view cannot be shown. Use the hlod command-line tool for headless work, or run the editor on a machine with an OpenGL 3.2 driver (Mesa&apos;s llvmpipe is enough).</source>
        <translation>OpenGL 3.2 är inte tillgängligt, så 3D-vyn kan inte visas. Använd kommandoradsverktyget hlod för arbete utan grafik, eller kör redigeraren på en dator med en OpenGL 3.2-drivrutin (Mesas llvmpipe räcker).</translation>
    </message>
    <message>
        <source>No OpenGL context could be created on this display.</source>
        <translation>Ingen OpenGL-kontext kunde skapas på den här skärmen.</translation>
    </message>
    <message>
        <source>An OpenGL context was created but could not be made current.</source>
        <translation>En OpenGL-kontext skapades men kunde inte aktiveras.</translation>
    </message>
    <message>
        <source>The driver offers OpenGL %1.%2 (%3), VTK needs 3.2 or newer.</source>
        <translation>Drivrutinen erbjuder OpenGL %1.%2 (%3), VTK behöver 3.2 eller senare.</translation>
    </message>
</context>
<context>
    <name>MainWindow</name>
    <message>
        <source>Sample scene</source>
        <translation>Exempelscen</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Arkiv</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>&amp;Öppna…</translation>
    </message>
    <message>
        <source>Open one or more scene files (several files form one scene)</source>
        <translation>Öppna en eller flera scenfiler (flera filer bildar en scen)</translation>
    </message>
    <message>
        <source>Open &amp;Folder…</source>
        <translation>Öppna &amp;mapp…</translation>
    </message>
    <message>
        <source>Open every loadable file in a folder as one scene</source>
        <translation>Öppna alla läsbara filer i en mapp som en scen</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>Öppna &amp;senaste</translation>
    </message>
    <message>
        <source>Open &amp;Sample Scene</source>
        <translation>Öppna &amp;exempelscen</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Avsluta</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Visa</translation>
    </message>
    <message>
        <source>&amp;Fit View</source>
        <translation>&amp;Anpassa vyn</translation>
    </message>
    <message>
        <source>Show the whole scene</source>
        <translation>Visa hela scenen</translation>
    </message>
    <message>
        <source>&amp;Reset View</source>
        <translation>Åte&amp;rställ vyn</translation>
    </message>
    <message>
        <source>Look at the whole scene from the front, right and above</source>
        <translation>Se hela scenen framifrån, från höger och ovanifrån</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Hjälp</translation>
    </message>
    <message>
        <source>&amp;About HLOD Studio</source>
        <translation>&amp;Om HLOD Studio</translation>
    </message>
    <message>
        <source>About &amp;Qt</source>
        <translation>Om &amp;Qt</translation>
    </message>
    <message>
        <source>Scene</source>
        <translation>Scen</translation>
    </message>
    <message>
        <source>Log</source>
        <translation>Logg</translation>
    </message>
    <message>
        <source>&amp;Clear List</source>
        <translation>&amp;Töm listan</translation>
    </message>
    <message>
        <source>Scenes (%1)</source>
        <translation>Scener (%1)</translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation>Alla filer (*)</translation>
    </message>
    <message>
        <source>Open Scene</source>
        <translation>Öppna scen</translation>
    </message>
    <message>
        <source>Open Folder as Scene</source>
        <translation>Öppna mapp som scen</translation>
    </message>
    <message>
        <source>OpenGL: available</source>
        <translation>OpenGL: tillgängligt</translation>
    </message>
    <message>
        <source>OpenGL: not available</source>
        <translation>OpenGL: inte tillgängligt</translation>
    </message>
    <message>
        <source>About HLOD Studio</source>
        <translation>Om HLOD Studio</translation>
    </message>
    <message>
        <source>&lt;h3&gt;HLOD Studio %1&lt;/h3&gt;&lt;p&gt;Builds Hierarchical Level-of-Detail for 3D scenes: clusters of meshes with simplified proxies, exported as 3D Tiles for any engine.&lt;/p&gt;&lt;p&gt;Qt %2, VTK %3. %4&lt;/p&gt;</source>
        <translation>&lt;h3&gt;HLOD Studio %1&lt;/h3&gt;&lt;p&gt;Bygger hierarkisk detaljnivå (HLOD) för 3D-scener: kluster av nät med förenklade ersättningsnät, exporterade som 3D Tiles för valfri motor.&lt;/p&gt;&lt;p&gt;Qt %2, VTK %3. %4&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Loading %1…</source>
        <translation>Läser in %1…</translation>
    </message>
    <message>
        <source>Opening the sample scene</source>
        <translation>Öppnar exempelscenen</translation>
    </message>
    <message>
        <source>Opening %1</source>
        <translation>Öppnar %1</translation>
    </message>
    <message>
        <source>Loaded %1: %2 instances, %3 triangles, %4 materials (import %5 s, render data %6 s, %7)</source>
        <translation>Läste in %1: %2 instanser, %3 trianglar, %4 material (import %5 s, renderingsdata %6 s, %7)</translation>
    </message>
    <message>
        <source>merged per material</source>
        <translation>sammanslaget per material</translation>
    </message>
    <message>
        <source>one actor per instance</source>
        <translation>en aktör per instans</translation>
    </message>
    <message>
        <source>Could not open %1</source>
        <translation>Kunde inte öppna %1</translation>
    </message>
    <message>
        <source>First frame in %1 ms</source>
        <translation>Första bilden efter %1 ms</translation>
    </message>
    <message>
        <source>HLOD Studio</source>
        <translation>HLOD Studio</translation>
    </message>
    <message>
        <source>%1 — %2</source>
        <translation>%1 — %2</translation>
    </message>
    <message>
        <source>No scene</source>
        <translation>Ingen scen</translation>
    </message>
    <message>
        <source>Instances: %1   Triangles: %2   Materials: %3</source>
        <translation>Instanser: %1   Trianglar: %2   Material: %3</translation>
    </message>
    <message>
        <source>%1: nothing was rendered</source>
        <translation>%1: ingenting renderades</translation>
    </message>
    <message>
        <source>%1: could not write the image</source>
        <translation>%1: bilden kunde inte skrivas</translation>
    </message>
    <message>
        <source>merged by opacity</source>
        <translation>sammanslaget efter opacitet</translation>
    </message>
</context>
<context>
    <name>RecentScenes</name>
    <message numerus="yes">
        <source>%1 + %n more</source>
        <translation>
            <numerusform>%1 + %n till</numerusform>
            <numerusform>%1 + %n till</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>hlod::widgets::LogView</name>
    <message>
        <source>Warning: </source>
        <translation>Varning: </translation>
    </message>
    <message>
        <source>Error: </source>
        <translation>Fel: </translation>
    </message>
</context>
<context>
    <name>hlod::widgets::SceneLoader</name>
    <message>
        <source>%1: not enough memory to load this scene</source>
        <translation>%1: inte tillräckligt med minne för att läsa in scenen</translation>
    </message>
    <message>
        <source>%1: unexpected error while loading</source>
        <translation>%1: oväntat fel vid inläsning</translation>
    </message>
</context>
<context>
    <name>hlod::widgets::SceneTreeModel</name>
    <message>
        <source>(unnamed %1)</source>
        <translation>(namnlös %1)</translation>
    </message>
    <message>
        <source>Node %1: %2 meshes, %3 triangles on this node; %4 meshes, %5 triangles including children</source>
        <translation>Nod %1: %2 nät, %3 trianglar i noden; %4 nät, %5 trianglar med barnnoder</translation>
    </message>
    <message>
        <source>Node</source>
        <translation>Nod</translation>
    </message>
    <message>
        <source>Meshes</source>
        <translation>Nät</translation>
    </message>
    <message>
        <source>Triangles</source>
        <translation>Trianglar</translation>
    </message>
</context>
<context>
    <name>hlod::widgets::Viewport</name>
    <message>
        <source>This widget received an OpenGL %1.%2 context.</source>
        <translation>Den här vyn fick en OpenGL %1.%2-kontext.</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>HLOD Studio: build and inspect Hierarchical Level-of-Detail for 3D scenes.</source>
        <translation>HLOD Studio: bygg och granska hierarkisk detaljnivå (HLOD) för 3D-scener.</translation>
    </message>
    <message>
        <source>Scene files or folders, opened as one scene.</source>
        <translation>Scenfiler eller mappar, öppnade som en scen.</translation>
    </message>
    <message>
        <source>Save a screenshot once loaded and rendered, then quit.</source>
        <translation>Spara en skärmbild när scenen är inläst och renderad, och avsluta sedan.</translation>
    </message>
    <message>
        <source>With --screenshot: save only the 3D view.</source>
        <translation>Med --screenshot: spara bara 3D-vyn.</translation>
    </message>
    <message>
        <source>Window size in pixels.</source>
        <translation>Fönsterstorlek i bildpunkter.</translation>
    </message>
    <message>
        <source>--size wants WIDTHxHEIGHT, at least 200x150, not &quot;%1&quot;</source>
        <translation>--size vill ha BREDDxHÖJD, minst 200x150, inte &quot;%1&quot;</translation>
    </message>
    <message>
        <source>Turn the initial view by AZ degrees around the up axis and tilt it by EL degrees, then fit.</source>
        <translation>Vrid startvyn AZ grader runt uppåtaxeln och luta den EL grader, och anpassa den sedan.</translation>
    </message>
    <message>
        <source>--orbit wants two angles in degrees, AZ,EL, not &quot;%1&quot;</source>
        <translation>--orbit vill ha två vinklar i grader, AZ,EL, inte &quot;%1&quot;</translation>
    </message>
</context>
</TS>
