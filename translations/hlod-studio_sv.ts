<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="sv_SE">
<context>
    <name>CompareConfig</name>
    <message>
        <source>Sphere</source>
        <translation>Sfär</translation>
    </message>
    <message>
        <source>AABB k=%1</source>
        <translation>AABB k=%1</translation>
    </message>
    <message>
        <source>Octree</source>
        <translation>Oktalträd</translation>
    </message>
    <message>
        <source>Original hierarchy</source>
        <translation>Ursprunglig hierarki</translation>
    </message>
    <message>
        <source>%1, S = %2 px</source>
        <translation>%1, S = %2 px</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: k applies to aabb only</source>
        <translation>&quot;%1&quot;: k gäller bara aabb</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: k must be within [%2, %3]</source>
        <translation>&quot;%1&quot;: k måste ligga inom [%2, %3]</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: the screen size must be within [%2, %3] px</source>
        <translation>&quot;%1&quot;: skärmstorleken måste ligga inom [%2, %3] px</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a pair of configurations LEFT:RIGHT, e.g. sphere:aabb-k2</source>
        <translation>&quot;%1&quot; är inget par av konfigurationer VÄNSTER:HÖGER, t.ex. sphere:aabb-k2</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a configuration: use #N (Bake node N), sphere, aabb, aabb-kK, octree, original or current, optionally followed by @S (screen size in pixels)</source>
        <translation>&quot;%1&quot; är ingen konfiguration: använd #N (bakningsnod N), sphere, aabb, aabb-kK, octree, original eller current, eventuellt följt av @S (skärmstorlek i pixlar)</translation>
    </message>
</context>
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
        <source>All files (*)</source>
        <translation>Alla filer (*)</translation>
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
    <message>
        <source>%1 (%2) — %3</source>
        <translation>%1 (%2) — %3</translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation>Parametrar</translation>
    </message>
    <message>
        <source>&lt;opened&gt;</source>
        <translation>&lt;öppnad&gt;</translation>
    </message>
    <message>
        <source>History</source>
        <translation>Historik</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Redigera</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Ångra</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Gör om</translation>
    </message>
    <message>
        <source>&amp;Clusters</source>
        <translation>&amp;Kluster</translation>
    </message>
    <message>
        <source>Clusters</source>
        <translation>Kluster</translation>
    </message>
    <message>
        <source>Statistics</source>
        <translation>Statistik</translation>
    </message>
    <message>
        <source>&amp;Build</source>
        <translation>&amp;Bygg</translation>
    </message>
    <message>
        <source>&amp;Build HLOD</source>
        <translation>&amp;Bygg HLOD</translation>
    </message>
    <message>
        <source>&amp;Cancel Build</source>
        <translation>&amp;Avbryt bygget</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Avbryt</translation>
    </message>
    <message>
        <source>Stop the running build; the previous HLOD stays</source>
        <translation>Stoppa det pågående bygget; föregående HLOD finns kvar</translation>
    </message>
    <message>
        <source>Building HLOD…</source>
        <translation>Bygger HLOD…</translation>
    </message>
    <message>
        <source>Clustering</source>
        <translation>Klustring</translation>
    </message>
    <message>
        <source>Baking proxies</source>
        <translation>Bakar proxyer</translation>
    </message>
    <message>
        <source>%1 %2/%3</source>
        <translation>%1 %2/%3</translation>
    </message>
    <message>
        <source>Meshing CAD faces</source>
        <translation>Nätar CAD-ytor</translation>
    </message>
    <message>
        <source>Converting CAD shapes (‰)</source>
        <translation>Konverterar CAD-former (‰)</translation>
    </message>
    <message>
        <source>Reading</source>
        <translation>Läser</translation>
    </message>
    <message>
        <source>Could not build the HLOD</source>
        <translation>Kunde inte bygga HLOD</translation>
    </message>
    <message>
        <source>HLOD build cancelled; the previous result stays</source>
        <translation>HLOD-bygget avbröts; föregående resultat finns kvar</translation>
    </message>
    <message>
        <source>the build was cancelled</source>
        <translation>bygget avbröts</translation>
    </message>
    <message>
        <source>HLOD projects (*%1)</source>
        <translation>HLOD-projekt (*%1)</translation>
    </message>
    <message>
        <source>Open &amp;Project…</source>
        <translation>Öppna &amp;projekt…</translation>
    </message>
    <message>
        <source>Open a .hlodproj project: its scene, parameters and hand edits</source>
        <translation>Öppna ett .hlodproj-projekt: dess scen, parametrar och handredigeringar</translation>
    </message>
    <message>
        <source>&amp;Save Project</source>
        <translation>&amp;Spara projekt</translation>
    </message>
    <message>
        <source>Save Project &amp;As…</source>
        <translation>Spara projekt &amp;som…</translation>
    </message>
    <message>
        <source>&amp;Export Package…</source>
        <translation>&amp;Exportera paket…</translation>
    </message>
    <message>
        <source>Open Project</source>
        <translation>Öppna projekt</translation>
    </message>
    <message>
        <source>Recover Project</source>
        <translation>Återställ projekt</translation>
    </message>
    <message>
        <source>%1 has an autosave newer than the project (the editor may have stopped before saving). Recover the autosaved changes?</source>
        <translation>%1 har en automatisk sparning som är nyare än projektet (redigeraren kan ha stoppats innan den sparade). Återställa de automatiskt sparade ändringarna?</translation>
    </message>
    <message>
        <source>Could not open the project</source>
        <translation>Kunde inte öppna projektet</translation>
    </message>
    <message>
        <source>Recovered %1 from its autosave</source>
        <translation>Återställde %1 från dess automatiska sparning</translation>
    </message>
    <message>
        <source>Opened project %1</source>
        <translation>Öppnade projektet %1</translation>
    </message>
    <message>
        <source>Could not save the project</source>
        <translation>Kunde inte spara projektet</translation>
    </message>
    <message>
        <source>Saved project %1</source>
        <translation>Sparade projektet %1</translation>
    </message>
    <message>
        <source>Save Project As</source>
        <translation>Spara projekt som</translation>
    </message>
    <message>
        <source>Unsaved Changes</source>
        <translation>Osparade ändringar</translation>
    </message>
    <message>
        <source>%1 has unsaved changes. Save them?</source>
        <translation>%1 har osparade ändringar. Spara dem?</translation>
    </message>
    <message>
        <source>Exported the package to %1 (%2 files)</source>
        <translation>Exporterade paketet till %1 (%2 filer)</translation>
    </message>
    <message>
        <source>&amp;Compare Configurations…</source>
        <translation>&amp;Jämför konfigurationer…</translation>
    </message>
    <message>
        <source>The document now uses %1 (from the comparison)</source>
        <translation>Dokumentet använder nu %1 (från jämförelsen)</translation>
    </message>
    <message>
        <source>Comparison, %1 side: %2</source>
        <translation>Jämförelse, %1 sida: %2</translation>
    </message>
    <message>
        <source>left</source>
        <translation>vänster</translation>
    </message>
    <message>
        <source>right</source>
        <translation>höger</translation>
    </message>
    <message>
        <source>Compare Configurations — %1</source>
        <translation>Jämför konfigurationer — %1</translation>
    </message>
    <message>
        <source>Comparing %1 with %2</source>
        <translation>Jämför %1 med %2</translation>
    </message>
    <message>
        <source>Pipeline</source>
        <translation>Pipeline</translation>
    </message>
    <message>
        <source>Open a project, or one or more scene files (several files form one scene)</source>
        <translation>Öppna ett projekt, eller en eller flera scenfiler (flera filer bildar en scen)</translation>
    </message>
    <message>
        <source>%1 is a project: open it on its own (its scene is in the project), not together with other files</source>
        <translation>%1 är ett projekt: öppna det ensamt (dess scen finns i projektet), inte tillsammans med andra filer</translation>
    </message>
    <message>
        <source>Scenes and projects (%1)</source>
        <translation>Scener och projekt (%1)</translation>
    </message>
    <message>
        <source>HLOD projects (%1)</source>
        <translation>HLOD-projekt (%1)</translation>
    </message>
    <message>
        <source>Open Scene or Project</source>
        <translation>Öppna scen eller projekt</translation>
    </message>
    <message>
        <source>Could not open the project %1</source>
        <translation>Kunde inte öppna projektet %1</translation>
    </message>
    <message>
        <source>Its scene could not be read: %1</source>
        <translation>Dess scen kunde inte läsas: %1</translation>
    </message>
    <message>
        <source>Recovering %1 from its autosave</source>
        <translation>Återställer %1 från dess automatiska sparning</translation>
    </message>
    <message>
        <source>Opening project %1</source>
        <translation>Öppnar projektet %1</translation>
    </message>
    <message>
        <source>Opened %1: building its HLOD…</source>
        <translation>Öppnade %1: bygger dess HLOD…</translation>
    </message>
    <message>
        <source>The Import node changed: reading the scene again</source>
        <translation>Importnoden har ändrats: scenen läses in igen</translation>
    </message>
    <message>
        <source>Compare two branches of this scene (two Bake nodes, or one and a quick configuration such as AABB k=2) side by side with linked cameras and statistics</source>
        <translation>Jämför två grenar av scenen (två bakningsnoder, eller en och en snabbkonfiguration som AABB k=2) sida vid sida med länkade kameror och statistik</translation>
    </message>
    <message>
        <source>--compare: the document has no Bake node #%1</source>
        <translation>--compare: dokumentet har ingen bakningsnod #%1</translation>
    </message>
    <message>
        <source>Branch </source>
        <translation>Gren </translation>
    </message>
    <message>
        <source>Run the shown branch (its Cluster and Bake nodes) in the background: only what changed runs</source>
        <translation>Kör den visade grenen (dess kluster- och bakningsnoder) i bakgrunden: bara det som ändrats körs</translation>
    </message>
    <message>
        <source>Build &amp;All Branches</source>
        <translation>Bygg &amp;alla grenar</translation>
    </message>
    <message>
        <source>Run every Bake node of the scene in the background</source>
        <translation>Kör alla bakningsnoder i scenen i bakgrunden</translation>
    </message>
    <message>
        <source>Running %1</source>
        <translation>Kör %1</translation>
    </message>
    <message>
        <source>%1: %2 nodes, height %3, %4 proxy triangles (cluster %5 s, bake %6 s: %7 baked, %8 reused)</source>
        <translation>%1: %2 noder, höjd %3, %4 proxytrianglar (klustring %5 s, bakning %6 s: %7 bakade, %8 återanvända)</translation>
    </message>
    <message>
        <source>Write the shown branch&apos;s package (its Export node) as 3D Tiles</source>
        <translation>Skriv den visade grenens paket (dess exportnod) som 3D Tiles</translation>
    </message>
    <message>
        <source>Export &amp;All Packages</source>
        <translation>Exportera &amp;alla paket</translation>
    </message>
    <message>
        <source>Run every Export node: each branch&apos;s package into its own folder</source>
        <translation>Kör alla exportnoder: varje grens paket i sin egen mapp</translation>
    </message>
    <message>
        <source>%1: wrote the package to %2 (%3 files)</source>
        <translation>%1: skrev paketet till %2 (%3 filer)</translation>
    </message>
    <message>
        <source>Exported %1 packages</source>
        <translation>Exporterade %1 paket</translation>
    </message>
</context>
<context>
    <name>NumberFormat</name>
    <message>
        <source>%1 k</source>
        <translation>%1 k</translation>
    </message>
    <message>
        <source>%1 M</source>
        <translation>%1 M</translation>
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
    <name>hlod::widgets::BranchBox</name>
    <message>
        <source>The branch whose HLOD the view, the Clusters tab and Statistics show (also: click its Bake node in the Pipeline dock)</source>
        <translation>Grenen vars HLOD vyn, klusterfliken och statistiken visar (eller: klicka på dess bakningsnod i pipelinepanelen)</translation>
    </message>
</context>
<context>
    <name>hlod::widgets::BuildParameters</name>
    <message>
        <source>Clustering</source>
        <translation>Klustring</translation>
    </message>
    <message>
        <source>Proxies</source>
        <translation>Proxyer</translation>
    </message>
    <message>
        <source>Build HLOD</source>
        <translation>Bygg HLOD</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Avbryt</translation>
    </message>
    <message>
        <source>Import (reading the scene)</source>
        <translation>Import (läsning av scenen)</translation>
    </message>
    <message>
        <source>Package</source>
        <translation>Paket</translation>
    </message>
    <message>
        <source>Click a node in the Pipeline dock to see and edit its parameters.</source>
        <translation>Klicka på en nod i pipelinepanelen för att se och ändra dess parametrar.</translation>
    </message>
    <message>
        <source>Run the shown branch (its Cluster and Bake nodes) with these parameters</source>
        <translation>Kör den visade grenen (dess kluster- och bakningsnoder) med dessa parametrar</translation>
    </message>
    <message>
        <source>%1 — %2</source>
        <translation>%1 — %2</translation>
    </message>
</context>
<context>
    <name>hlod::widgets::ClusterEditActions</name>
    <message>
        <source>&amp;Merge Clusters</source>
        <translation>&amp;Slå ihop kluster</translation>
    </message>
    <message>
        <source>Make the selected clusters one locked cluster, then rebuild</source>
        <translation>Gör de valda klustren till ett låst kluster och bygg om</translation>
    </message>
    <message>
        <source>&amp;Lock Cluster</source>
        <translation>&amp;Lås kluster</translation>
    </message>
    <message>
        <source>Keep the selected clusters whole when clustering reruns</source>
        <translation>Håll de valda klustren hela när klustringen körs om</translation>
    </message>
    <message>
        <source>&amp;Unlock Cluster</source>
        <translation>&amp;Lås upp kluster</translation>
    </message>
    <message>
        <source>&amp;Exclude from HLOD</source>
        <translation>&amp;Undanta från HLOD</translation>
    </message>
    <message>
        <source>Hang the selected meshes directly from the root, never merged</source>
        <translation>Häng de valda näten direkt under roten, aldrig sammanslagna</translation>
    </message>
    <message>
        <source>&amp;Split Cluster</source>
        <translation>&amp;Dela kluster</translation>
    </message>
    <message>
        <source>Remove the selected cluster: its children hang from its parent</source>
        <translation>Ta bort det markerade klustret: dess barn hänger från dess förälder</translation>
    </message>
    <message>
        <source>Let clustering regroup the selected locked clusters</source>
        <translation>Låt klustringen gruppera om de markerade låsta klustren</translation>
    </message>
    <message>
        <source>&amp;Include in HLOD</source>
        <translation>&amp;Ta med i HLOD</translation>
    </message>
    <message>
        <source>Cluster the selected excluded meshes again</source>
        <translation>Klustra de markerade uteslutna näten igen</translation>
    </message>
    <message>
        <source>Mo&amp;ve to Cluster</source>
        <translation>&amp;Flytta till kluster</translation>
    </message>
    <message>
        <source>Move the other selected meshes and clusters into the current cluster (the row clicked last)</source>
        <translation>Flytta de övriga markerade näten och klustren till det aktuella klustret (raden som klickades senast)</translation>
    </message>
</context>
<context>
    <name>hlod::widgets::ClusterTreeModel</name>
    <message>
        <source>Cluster %1</source>
        <translation>Kluster %1</translation>
    </message>
    <message>
        <source>Instance %1</source>
        <translation>Instans %1</translation>
    </message>
    <message>
        <source>Cluster</source>
        <translation>Kluster</translation>
    </message>
    <message>
        <source>Triangles</source>
        <translation>Trianglar</translation>
    </message>
    <message>
        <source>Level</source>
        <translation>Nivå</translation>
    </message>
    <message>
        <source>Cluster %1 (locked)</source>
        <translation>Kluster %1 (låst)</translation>
    </message>
    <message>
        <source>%1 triangles below, %2 across, volume %3</source>
        <translation>%1 trianglar under, %2 tvärsöver, volym %3</translation>
    </message>
    <message>
        <source>%1: mesh instance %2, %3</source>
        <translation>%1: nätinstans %2, %3</translation>
    </message>
    <message>
        <source>%1: %2 children, %3, proxy %4 triangles, fill %5%6</source>
        <translation>%1: %2 barn, %3, proxy %4 trianglar, fyllnad %5%6</translation>
    </message>
    <message>
        <source>; locked by a hand edit: kept whole when clustering reruns</source>
        <translation>; låst av en handredigering: hålls samman när klustringen körs om</translation>
    </message>
    <message>
        <source>Triangles of the original meshes below the cluster</source>
        <translation>Trianglar i originalnäten under klustret</translation>
    </message>
    <message>
        <source>Triangles of the cluster&apos;s proxy, drawn in place of everything below it</source>
        <translation>Trianglar i klustrets proxy, som ritas i stället för allt under det</translation>
    </message>
    <message>
        <source>Level in the tree: 0 for single meshes, the root highest</source>
        <translation>Nivå i trädet: 0 för enskilda nät, roten högst</translation>
    </message>
    <message>
        <source>Diameter of the cluster&apos;s bounding sphere (sphere trees) or diagonal of its box</source>
        <translation>Diameter för klustrets omslutande sfär (sfärträd) eller diagonal för dess låda</translation>
    </message>
    <message>
        <source>Size</source>
        <translation>Storlek</translation>
    </message>
    <message>
        <source>Proxy</source>
        <translation>Proxy</translation>
    </message>
</context>
<context>
    <name>hlod::widgets::ComparePane</name>
    <message>
        <source>Sphere</source>
        <translation>Sfär</translation>
    </message>
    <message>
        <source>AABB</source>
        <translation>AABB</translation>
    </message>
    <message>
        <source>Octree</source>
        <translation>Oktalträd</translation>
    </message>
    <message>
        <source>Original hierarchy</source>
        <translation>Ursprunglig hierarki</translation>
    </message>
    <message>
        <source> px</source>
        <translation> px</translation>
    </message>
    <message>
        <source>Use These Settings</source>
        <translation>Använd dessa inställningar</translation>
    </message>
    <message>
        <source>Volume</source>
        <translation>Volym</translation>
    </message>
    <message>
        <source>k</source>
        <translation>k</translation>
    </message>
    <message>
        <source>Screen size</source>
        <translation>Skärmstorlek</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Avbryt</translation>
    </message>
    <message>
        <source>Stop this side&apos;s build</source>
        <translation>Stoppa den här sidans bygge</translation>
    </message>
    <message>
        <source>Build failed: %1</source>
        <translation>Bygget misslyckades: %1</translation>
    </message>
    <message>
        <source>Cancelled</source>
        <translation>Avbrutet</translation>
    </message>
    <message>
        <source>No scene</source>
        <translation>Ingen scen</translation>
    </message>
    <message>
        <source>Not built</source>
        <translation>Inte byggd</translation>
    </message>
    <message>
        <source>Building %1…</source>
        <translation>Bygger %1…</translation>
    </message>
    <message>
        <source>Clustering</source>
        <translation>Klustring</translation>
    </message>
    <message>
        <source>Baking proxies</source>
        <translation>Bakar proxyer</translation>
    </message>
    <message>
        <source>%1: %2 %3/%4</source>
        <translation>%1: %2 %3/%4</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>%1 nodes, height %2; built in %3 s (%4 proxies baked, %5 from the cache)</source>
        <translation>%1 noder, höjd %2; byggd på %3 s (%4 proxyer bakade, %5 från cachen)</translation>
    </message>
    <message>
        <source>A Bake node of the document, or Custom: the values on the right over the shown branch (built as a temporary branch, the document is not changed)</source>
        <translation>En bakningsnod i dokumentet, eller Anpassad: värdena till höger över den visade grenen (byggs som en tillfällig gren, dokumentet ändras inte)</translation>
    </message>
    <message>
        <source>Set the volume, k and screen size of the branch this side is laid over to this side&apos;s values (one step in Edit ▸ Undo)</source>
        <translation>Sätt volym, k och skärmstorlek för grenen som den här sidan bygger på till den här sidans värden (ett steg i Redigera ▸ Ångra)</translation>
    </message>
    <message>
        <source>Custom</source>
        <translation>Anpassad</translation>
    </message>
    <message>
        <source>%1 (over %2)</source>
        <translation>%1 (över %2)</translation>
    </message>
    <message>
        <source>The document has no Import node to build from</source>
        <translation>Dokumentet har ingen importnod att bygga från</translation>
    </message>
</context>
<context>
    <name>hlod::widgets::CompareTable</name>
    <message>
        <source>Left</source>
        <translation>Vänster</translation>
    </message>
    <message>
        <source>Right</source>
        <translation>Höger</translation>
    </message>
    <message>
        <source>Draw calls (now)</source>
        <translation>Ritanrop (nu)</translation>
    </message>
    <message>
        <source>Triangles (now)</source>
        <translation>Trianglar (nu)</translation>
    </message>
    <message>
        <source>Tree nodes</source>
        <translation>Trädnoder</translation>
    </message>
    <message>
        <source>Proxy triangles</source>
        <translation>Proxytrianglar</translation>
    </message>
    <message>
        <source>Draw calls of the current frame for the linked camera (HLOD preview)</source>
        <translation>Ritanrop i den aktuella bilden för den länkade kameran (HLOD-förhandsvisning)</translation>
    </message>
    <message>
        <source>Triangles drawn in the current frame for the linked camera</source>
        <translation>Trianglar som ritas i den aktuella bilden för den länkade kameran</translation>
    </message>
    <message>
        <source>Nodes of the cluster tree: leaves (one per mesh instance) and clusters</source>
        <translation>Klusterträdets noder: löv (ett per nätinstans) och kluster</translation>
    </message>
    <message>
        <source>Triangles of all proxies of the inner nodes together</source>
        <translation>Trianglar i alla de inre nodernas proxyer tillsammans</translation>
    </message>
    <message>
        <source>Lower is better.</source>
        <translation>Lägre är bättre.</translation>
    </message>
    <message>
        <source>%1 bytes</source>
        <translation>%1 byte</translation>
    </message>
    <message>
        <source>Package on disk</source>
        <translation>Paket på disk</translation>
    </message>
    <message>
        <source>Bytes on disk of the package hlod build writes for this side (compressed, the allocated blocks of all its files): the figure hlod build prints</source>
        <translation>Byte på disk för paketet som hlod build skriver för den här sidan (komprimerat, de allokerade blocken för alla dess filer): siffran hlod build skriver ut</translation>
    </message>
</context>
<context>
    <name>hlod::widgets::CompareView</name>
    <message>
        <source>Left</source>
        <translation>Vänster</translation>
    </message>
    <message>
        <source>Right</source>
        <translation>Höger</translation>
    </message>
    <message>
        <source>Link cameras</source>
        <translation>Länka kameror</translation>
    </message>
    <message>
        <source>Orbiting, panning or zooming one side moves the other the same way</source>
        <translation>Att rotera, panorera eller zooma den ena sidan flyttar den andra på samma sätt</translation>
    </message>
    <message>
        <source>Fit View</source>
        <translation>Anpassa vy</translation>
    </message>
    <message>
        <source>Show the whole scene in both views (F)</source>
        <translation>Visa hela scenen i båda vyerna (F)</translation>
    </message>
    <message>
        <source>Rebuild Both</source>
        <translation>Bygg om båda</translation>
    </message>
    <message>
        <source>Compare Configurations</source>
        <translation>Jämför konfigurationer</translation>
    </message>
    <message>
        <source>The document already uses %1.</source>
        <translation>Dokumentet använder redan %1.</translation>
    </message>
    <message>
        <source>The document now uses %1 (Edit ▸ Undo takes it back).</source>
        <translation>Dokumentet använder nu %1 (Redigera ▸ Ångra tar tillbaka det).</translation>
    </message>
    <message>
        <source>Left: %1</source>
        <translation>Vänster: %1</translation>
    </message>
    <message>
        <source>Right: %1</source>
        <translation>Höger: %1</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Stäng</translation>
    </message>
    <message>
        <source>Close the comparison (Esc); its builds stop</source>
        <translation>Stäng jämförelsen (Esc); dess byggen stoppas</translation>
    </message>
    <message>
        <source>Build both sides again from the document&apos;s current graph</source>
        <translation>Bygg båda sidorna igen från dokumentets nuvarande graf</translation>
    </message>
</context>
<context>
    <name>hlod::widgets::DisplayController</name>
    <message>
        <source>Level %1 of %2: %3 clusters</source>
        <translation>Nivå %1 av %2: %3 kluster</translation>
    </message>
    <message>
        <source>Draw calls: %1
Triangles: %2
Nodes visited: %3</source>
        <translation>Ritanrop: %1
Trianglar: %2
Besökta noder: %3</translation>
    </message>
    <message>
        <source>Level %1: one colour per cluster</source>
        <translation>Nivå %1: en färg per kluster</translation>
    </message>
    <message>
        <source>Mesh %1</source>
        <translation>Nät %1</translation>
    </message>
    <message>
        <source>Cluster %1</source>
        <translation>Kluster %1</translation>
    </message>
    <message>
        <source>1 more cluster</source>
        <translation>1 kluster till</translation>
    </message>
    <message>
        <source>%1 more clusters</source>
        <translation>%1 kluster till</translation>
    </message>
    <message>
        <source>Tint: depth in the tree</source>
        <translation>Toning: djup i trädet</translation>
    </message>
    <message>
        <source>Depth 0 (root)</source>
        <translation>Djup 0 (roten)</translation>
    </message>
    <message>
        <source>Depth %1</source>
        <translation>Djup %1</translation>
    </message>
    <message>
        <source>Selected</source>
        <translation>Markerat</translation>
    </message>
    <message>
        <source>Level %1 of %2: 1 cluster</source>
        <translation>Nivå %1 av %2: 1 kluster</translation>
    </message>
</context>
<context>
    <name>hlod::widgets::DisplayToolBar</name>
    <message>
        <source>Display</source>
        <translation>Visning</translation>
    </message>
    <message>
        <source>Original</source>
        <translation>Original</translation>
    </message>
    <message>
        <source>Show the original scene</source>
        <translation>Visa originalscenen</translation>
    </message>
    <message>
        <source>Clusters</source>
        <translation>Kluster</translation>
    </message>
    <message>
        <source>Colour the meshes by their cluster at the chosen level</source>
        <translation>Färga näten efter deras kluster på vald nivå</translation>
    </message>
    <message>
        <source>HLOD preview</source>
        <translation>HLOD-förhandsvisning</translation>
    </message>
    <message>
        <source>Draw what an engine draws for this camera: proxies and leaves</source>
        <translation>Rita det en motor ritar för den här kameran: proxyer och löv</translation>
    </message>
    <message>
        <source> Level </source>
        <translation> Nivå </translation>
    </message>
    <message>
        <source>Cluster level shown in Clusters mode (0 = single meshes)</source>
        <translation>Klusternivå som visas i klusterläget (0 = enskilda nät)</translation>
    </message>
    <message>
        <source>No bounds</source>
        <translation>Inga volymer</translation>
    </message>
    <message>
        <source>Spheres</source>
        <translation>Sfärer</translation>
    </message>
    <message>
        <source>Boxes</source>
        <translation>Lådor</translation>
    </message>
    <message>
        <source>Bounding volumes drawn as wireframes in Clusters mode</source>
        <translation>Omslutande volymer ritade som trådmodeller i klusterläget</translation>
    </message>
    <message>
        <source>Selected only</source>
        <translation>Endast valda</translation>
    </message>
    <message>
        <source>Draw the bounds of the selected cluster&apos;s subtree only</source>
        <translation>Rita bara volymerna för det valda klustrets delträd</translation>
    </message>
    <message>
        <source>Tint by depth</source>
        <translation>Tona efter djup</translation>
    </message>
    <message>
        <source>HLOD preview: colour every drawn node by its depth in the tree</source>
        <translation>HLOD-förhandsvisning: färga varje ritad nod efter dess djup i trädet</translation>
    </message>
</context>
<context>
    <name>hlod::widgets::ExportDialog</name>
    <message>
        <source>The package folder: tileset.json, tiles/*.glb and hlod.json</source>
        <translation>Paketmappen: tileset.json, tiles/*.glb och hlod.json</translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation>Bläddra…</translation>
    </message>
    <message>
        <source>Include the DLOD chain statistics (slower)</source>
        <translation>Ta med statistik för DLOD-kedjan (långsammare)</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Exportera</translation>
    </message>
    <message>
        <source>Folder:</source>
        <translation>Mapp:</translation>
    </message>
    <message>
        <source>Export cancelled; nothing was written</source>
        <translation>Exporten avbröts; inget skrevs</translation>
    </message>
    <message>
        <source>Export Package To</source>
        <translation>Exportera paket till</translation>
    </message>
    <message>
        <source>Choose a folder for the package</source>
        <translation>Välj en mapp för paketet</translation>
    </message>
    <message>
        <source>Exporting…</source>
        <translation>Exporterar…</translation>
    </message>
    <message>
        <source>%1 %2/%3</source>
        <translation>%1 %2/%3</translation>
    </message>
    <message>
        <source>Wrote %1 files (%2) to %3</source>
        <translation>Skrev %1 filer (%2) till %3</translation>
    </message>
    <message>
        <source>Export Package — %1</source>
        <translation>Exportera paket — %1</translation>
    </message>
    <message>
        <source>Branch: %1</source>
        <translation>Gren: %1</translation>
    </message>
    <message>
        <source>Nothing to export: open a scene first</source>
        <translation>Inget att exportera: öppna en scen först</translation>
    </message>
    <message>
        <source>The export did not finish (the document changed meanwhile)</source>
        <translation>Exporten blev inte klar (dokumentet ändrades under tiden)</translation>
    </message>
</context>
<context>
    <name>hlod::widgets::GraphRunner</name>
    <message>
        <source>Not enough memory to build the HLOD of this scene</source>
        <translation>Inte tillräckligt med minne för att bygga HLOD för den här scenen</translation>
    </message>
    <message>
        <source>Unexpected error while building the HLOD</source>
        <translation>Oväntat fel när HLOD byggdes</translation>
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
    <name>hlod::widgets::NodeGraphView</name>
    <message>
        <source>Import</source>
        <translation>Import</translation>
    </message>
    <message>
        <source>Cluster</source>
        <translation>Kluster</translation>
    </message>
    <message>
        <source>Bake</source>
        <translation>Bakning</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Exportera</translation>
    </message>
    <message>
        <source>up to date</source>
        <translation>aktuell</translation>
    </message>
    <message>
        <source>pending</source>
        <translation>väntar</translation>
    </message>
    <message>
        <source>running</source>
        <translation>kör</translation>
    </message>
    <message>
        <source>failed</source>
        <translation>misslyckades</translation>
    </message>
    <message>
        <source>&amp;Remove %1</source>
        <translation>&amp;Ta bort %1</translation>
    </message>
    <message>
        <source>&amp;Disconnect</source>
        <translation>&amp;Koppla från</translation>
    </message>
    <message>
        <source>Add %1 Node</source>
        <translation>Lägg till %1-nod</translation>
    </message>
    <message>
        <source>sample scene</source>
        <translation>exempelscen</translation>
    </message>
    <message>
        <source>%1 + %2 more</source>
        <translation>%1 + %2 till</translation>
    </message>
    <message>
        <source>%1%2, ≤ %3 children</source>
        <translation>%1%2, ≤ %3 barn</translation>
    </message>
    <message>
        <source>S %1 px, %2</source>
        <translation>S %1 px, %2</translation>
    </message>
    <message>
        <source>no output folder</source>
        <translation>ingen utmapp</translation>
    </message>
    <message>
        <source>to %1</source>
        <translation>till %1</translation>
    </message>
    <message>
        <source>running %1%</source>
        <translation>kör %1%</translation>
    </message>
    <message>
        <source>Package written to %1</source>
        <translation>Paketet skrevs till %1</translation>
    </message>
    <message>
        <source>Shown in the 3D view</source>
        <translation>Visas i 3D-vyn</translation>
    </message>
    <message>
        <source>D&amp;uplicate %1</source>
        <translation>D&amp;uplicera %1</translation>
    </message>
    <message>
        <source>Duplicate &amp;Branch</source>
        <translation>Duplicera &amp;gren</translation>
    </message>
    <message>
        <source>Copy this node and everything downstream of it: a second variant fed by the same input</source>
        <translation>Kopiera noden och allt nedströms om den: en andra variant som matas av samma indata</translation>
    </message>
    <message>
        <source>&amp;Rename…</source>
        <translation>&amp;Byt namn…</translation>
    </message>
    <message>
        <source>&amp;Fit View</source>
        <translation>&amp;Anpassa vyn</translation>
    </message>
</context>
<context>
    <name>hlod::widgets::PipelineEditor</name>
    <message>
        <source>Add Node</source>
        <translation>Lägg till nod</translation>
    </message>
    <message>
        <source>Import</source>
        <translation>Import</translation>
    </message>
    <message>
        <source>Cluster</source>
        <translation>Kluster</translation>
    </message>
    <message>
        <source>Bake</source>
        <translation>Bakning</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Exportera</translation>
    </message>
    <message>
        <source>Add a node: after the selected node when it can take its output</source>
        <translation>Lägg till en nod: efter den valda noden när den kan ta dess utdata</translation>
    </message>
    <message>
        <source>Fit</source>
        <translation>Anpassa</translation>
    </message>
    <message>
        <source>Show the whole graph (F)</source>
        <translation>Visa hela grafen (F)</translation>
    </message>
    <message>
        <source>Click: parameters (a Bake node: shown) · drag output to input: connect · right-click: duplicate branch, rename, remove · F: fit</source>
        <translation>Klick: parametrar (en bakningsnod: visas) · dra utgång till ingång: koppla · högerklick: duplicera gren, byt namn, ta bort · F: anpassa</translation>
    </message>
    <message>
        <source>%1 %2/%3</source>
        <translation>%1 %2/%3</translation>
    </message>
    <message>
        <source>Rename Node</source>
        <translation>Byt namn på nod</translation>
    </message>
    <message>
        <source>Name of %1 (empty for none; hlod build --export NAME picks an Export by it):</source>
        <translation>Namn på %1 (tomt för inget; hlod build --export NAMN väljer en export med det):</translation>
    </message>
</context>
<context>
    <name>hlod::widgets::ProjectSession</name>
    <message>
        <source>Untitled</source>
        <translation>Namnlös</translation>
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
    <name>hlod::widgets::StatsPanel</name>
    <message>
        <source>Triangles</source>
        <translation>Trianglar</translation>
    </message>
    <message>
        <source>Vertices</source>
        <translation>Hörn</translation>
    </message>
    <message>
        <source>Meshes</source>
        <translation>Nät</translation>
    </message>
    <message>
        <source>Original</source>
        <translation>Original</translation>
    </message>
    <message>
        <source>HLOD</source>
        <translation>HLOD</translation>
    </message>
    <message>
        <source>Build the HLOD (Build ▸ Build HLOD, Ctrl+B) to compare.</source>
        <translation>Bygg HLOD (Bygg ▸ Bygg HLOD, Ctrl+B) för att jämföra.</translation>
    </message>
    <message>
        <source>Size</source>
        <translation>Storlek</translation>
    </message>
    <message>
        <source>The original meshes plus every proxy: what the package stores (as in the thesis&apos; tables), not what is drawn at once</source>
        <translation>Originalnäten plus alla proxyer: det paketet lagrar (som i avhandlingens tabeller), inte det som ritas samtidigt</translation>
    </message>
    <message>
        <source>Level</source>
        <translation>Nivå</translation>
    </message>
    <message>
        <source>Nodes</source>
        <translation>Noder</translation>
    </message>
    <message>
        <source>Children</source>
        <translation>Barn</translation>
    </message>
    <message>
        <source>Budget</source>
        <translation>Budget</translation>
    </message>
    <message>
        <source>Share</source>
        <translation>Andel</translation>
    </message>
    <message>
        <source>Level in the tree: 0 holds the original meshes</source>
        <translation>Nivå i trädet: 0 rymmer originalnäten</translation>
    </message>
    <message>
        <source>Clusters (level 0: meshes) on this level</source>
        <translation>Kluster (nivå 0: nät) på den här nivån</translation>
    </message>
    <message>
        <source>Mean number of children of this level&apos;s clusters</source>
        <translation>Medelantal barn för den här nivåns kluster</translation>
    </message>
    <message>
        <source>Error budget: how far a proxy of this level may deviate from what it replaces (pixel error × cluster diameter / screen size)</source>
        <translation>Felbudget: hur långt en proxy på den här nivån får avvika från det den ersätter (pixelfel × klusterdiameter / skärmstorlek)</translation>
    </message>
    <message>
        <source>Triangles of all proxies of this level (level 0: of the original meshes)</source>
        <translation>Trianglar i alla proxyer på den här nivån (nivå 0: i originalnäten)</translation>
    </message>
    <message>
        <source>Those triangles as a share of the original scene&apos;s</source>
        <translation>De trianglarna som andel av originalscenens</translation>
    </message>
    <message>
        <source>Geometry as the package&apos;s GLB files store it</source>
        <translation>Geometri så som paketets GLB-filer lagrar den</translation>
    </message>
    <message>
        <source>Proxy economy: 1 cluster dissolved</source>
        <translation>Proxyekonomi: 1 kluster upplöst</translation>
    </message>
    <message>
        <source>Proxy economy: %1 clusters dissolved</source>
        <translation>Proxyekonomi: %1 kluster upplösta</translation>
    </message>
    <message>
        <source>(a proxy must hold at most %1 of the triangles it replaces; a dissolved cluster&apos;s children hang from its parent).</source>
        <translation>(en proxy får ha högst %1 av trianglarna den ersätter; ett upplöst klusters barn hänger från dess förälder).</translation>
    </message>
    <message>
        <source>%1: %2 nodes, height %3; %4 proxies baked, %5 reused; built in %6 s</source>
        <translation>%1: %2 noder, höjd %3; %4 proxyer bakade, %5 återanvända; byggd på %6 s</translation>
    </message>
    <message>
        <source>Level 0: the original meshes</source>
        <translation>Nivå 0: originalnäten</translation>
    </message>
    <message>
        <source>the root&apos;s alone %1</source>
        <translation>rotens ensam %1</translation>
    </message>
    <message>
        <source>the root has none: it always draws its children</source>
        <translation>roten har ingen: den ritar alltid sina barn</translation>
    </message>
    <message>
        <source>HLOD: the original meshes plus all %1 proxies, as the thesis&apos; tables count it: what the package stores, not what is drawn at once. The proxies hold %2 triangles, %3 of the original (%4).</source>
        <translation>HLOD: originalnäten plus alla %1 proxyer, som avhandlingens tabeller räknar: det paketet lagrar, inte det som ritas samtidigt. Proxyerna har %2 trianglar, %3 av originalet (%4).</translation>
    </message>
    <message>
        <source>No Bake node is shown: pick a branch in the toolbar or click a Bake node</source>
        <translation>Ingen bakningsnod visas: välj en gren i verktygsfältet eller klicka på en bakningsnod</translation>
    </message>
    <message>
        <source>not built yet</source>
        <translation>inte byggd än</translation>
    </message>
    <message>
        <source>up to date</source>
        <translation>aktuell</translation>
    </message>
    <message>
        <source>building; its last build shown</source>
        <translation>byggs; dess senaste bygge visas</translation>
    </message>
    <message>
        <source>changed since this build</source>
        <translation>ändrad sedan det här bygget</translation>
    </message>
    <message>
        <source>&lt;b&gt;Branch:&lt;/b&gt; %1 (%2)</source>
        <translation>&lt;b&gt;Gren:&lt;/b&gt; %1 (%2)</translation>
    </message>
</context>
<context>
    <name>hlod::widgets::StatsPlot</name>
    <message>
        <source>draw calls %1</source>
        <translation>ritanrop %1</translation>
    </message>
    <message>
        <source>triangles %1</source>
        <translation>trianglar %1</translation>
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
    <message>
        <source>--mode wants original, clusters or hlod, not &quot;%1&quot;</source>
        <translation>--mode vill ha original, clusters eller hlod, inte &quot;%1&quot;</translation>
    </message>
    <message>
        <source>--level wants a cluster level (0 or more), not &quot;%1&quot;</source>
        <translation>--level vill ha en klusternivå (0 eller mer), inte &quot;%1&quot;</translation>
    </message>
    <message>
        <source>Build the HLOD once the scene is loaded.</source>
        <translation>Bygg HLOD när scenen har laddats.</translation>
    </message>
    <message>
        <source>Display mode: original, clusters or hlod (the last two build the HLOD first).</source>
        <translation>Visningsläge: original, clusters eller hlod (de två sista bygger HLOD först).</translation>
    </message>
    <message>
        <source>Cluster level shown in clusters mode.</source>
        <translation>Klusternivå som visas i klusterläget.</translation>
    </message>
    <message>
        <source>HLOD preview: tint drawn nodes by tree depth.</source>
        <translation>HLOD-förhandsvisning: tona ritade noder efter träddjup.</translation>
    </message>
    <message>
        <source>Scene files or folders, opened as one scene; or one .hlodproj project (its scene, parameters and hand edits, built and shown).</source>
        <translation>Scenfiler eller mappar, som öppnas som en scen; eller ett .hlodproj-projekt (dess scen, parametrar och handredigeringar, byggt och visat).</translation>
    </message>
    <message>
        <source>no display to open a window on (DISPLAY and WAYLAND_DISPLAY are unset). Run it in a desktop session or under xvfb-run -a, or use the hlod command-line tool (hlod --help).</source>
        <translation>ingen skärm att öppna ett fönster på (DISPLAY och WAYLAND_DISPLAY är inte satta). Kör den i en skrivbordssession eller under xvfb-run -a, eller använd kommandoradsverktyget hlod (hlod --help).</translation>
    </message>
    <message>
        <source>Build every branch (each Bake node of the pipeline) once the scene is loaded.</source>
        <translation>Bygg alla grenar (varje bakningsnod i pipelinen) när scenen har lästs in.</translation>
    </message>
    <message>
        <source>Compare two branches side by side, e.g. sphere:aabb-k2 (also octree, original, current, @S for the screen size; #N: Bake node N).</source>
        <translation>Jämför två grenar sida vid sida, t.ex. sphere:aabb-k2 (även octree, original, current, @S för skärmstorleken; #N: bakningsnod N).</translation>
    </message>
</context>
</TS>
