// A structural AC3D reader that keeps only the object tree, names, first texture lines, vertex
// counts and surface headers, see Ac3dTextures.h. Vertex lines and surface references are
// skipped by their declared counts.
#include "pipeline/io/Ac3dTextures.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace hlod {

namespace {

// A quoted string ("a b") or the next whitespace-delimited token.
std::string stringArgument(std::istringstream& line) {
    line >> std::ws;
    if (line.peek() == '"') {
        line.get();
        std::string value;
        std::getline(line, value, '"');
        return value;
    }
    std::string token;
    line >> token;
    return token;
}

class Parser {
public:
    explicit Parser(const std::string& text) : in_(text) {}

    // Reads objects until `count` are read, or the file ends: a kids count larger than the
    // objects that follow ends the list early, as in assimp ("wrong number of kids"; TORCS's
    // spring.acc declares one kid more than it has).
    std::size_t materials = 0; // MATERIAL lines seen

    bool readObjects(std::vector<Ac3dObject>& out, std::size_t count, bool topLevel, int depth) {
        if (depth > 1000) return false;
        std::string line;
        while ((topLevel || out.size() < count) && next(line)) {
            if (line.rfind("OBJECT", 0) != 0) {
                if (!topLevel) return false;
                if (line.rfind("MATERIAL", 0) == 0) ++materials;
                continue; // the header
            }
            out.emplace_back();
            if (!readBody(out.back(), depth)) return false;
        }
        return true;
    }

private:
    bool next(std::string& line) {
        while (std::getline(in_, line)) {
            const auto start = line.find_first_not_of(" \t\r");
            if (start == std::string::npos) continue;
            line.erase(0, start);
            return true;
        }
        return false;
    }

    bool skipLines(std::size_t n) {
        std::string line;
        for (std::size_t i = 0; i < n; ++i)
            if (!std::getline(in_, line)) return false;
        return true;
    }

    bool readSurfaces(std::size_t n, std::vector<Ac3dSurface>& out) {
        std::string line;
        for (std::size_t s = 0; s < n; ++s) {
            // SURF flags, optional mat, refs M: read up to the refs line.
            Ac3dSurface surface;
            while (true) {
                if (!next(line)) return false;
                if (line.rfind("refs", 0) == 0) break;
                std::istringstream ls(line.substr(line.rfind("SURF", 0) == 0 ? 4 : 3));
                if (line.rfind("SURF", 0) == 0) {
                    std::string flags;
                    ls >> flags;
                    surface.flags = static_cast<unsigned>(std::strtoul(flags.c_str(), nullptr, 0));
                } else if (line.rfind("mat", 0) == 0) {
                    ls >> surface.material;
                } else {
                    return false;
                }
            }
            std::istringstream ls(line.substr(4));
            if (!(ls >> surface.refs) || !skipLines(surface.refs)) return false;
            out.push_back(surface);
        }
        return true;
    }

    bool readBody(Ac3dObject& object, int depth) {
        std::string line;
        while (next(line)) {
            std::istringstream ls(line);
            std::string token;
            ls >> token;
            std::size_t n = 0;
            if (token == "name") {
                object.name = stringArgument(ls);
            } else if (token == "texture") {
                if (object.firstTexture.empty()) object.firstTexture = stringArgument(ls);
            } else if (token == "numvert") {
                if (!(ls >> n) || !skipLines(n)) return false;
                object.vertices = n;
            } else if (token == "numsurf") {
                if (!(ls >> n) || !readSurfaces(n, object.surfaces)) return false;
            } else if (token == "kids") {
                if (!(ls >> n)) return false;
                return readObjects(object.kids, n, false, depth + 1);
            }
        }
        return false; // every object ends with its kids line
    }

    std::istringstream in_;
};

} // namespace

std::optional<Ac3dFile> parseAc3dFile(const std::string& text) {
    if (text.rfind("AC3D", 0) != 0) return std::nullopt;
    Parser parser(text);
    Ac3dFile file;
    if (!parser.readObjects(file.objects, 0, true, 0)) return std::nullopt;
    file.materials = parser.materials;
    return file;
}

std::optional<Ac3dFile> readAc3dFile(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return std::nullopt;
    std::ostringstream text;
    text << in.rdbuf();
    return parseAc3dFile(text.str());
}

namespace {

// assimp's per-material face count of a surface (ConvertObjectSection's needMat, unsigned
// arithmetic included): a material gets an aiMaterial when its count is not zero.
unsigned facesOf(const Ac3dSurface& s) {
    const auto refs = static_cast<unsigned>(s.refs);
    switch (s.flags & 0xfu) {
    case 1: // closed line
        return refs;
    case 2: // line
        return refs - 1u;
    case 4: // triangle strip
        return refs - 2u;
    default: // polygon (unknown types are read as polygons)
        return 1u;
    }
}

void appendMaterialSides(const Ac3dObject& object, std::size_t fileMaterials,
                         std::vector<bool>& out, int depth) {
    if (depth > 1000) return;
    if (object.vertices > 0) {
        std::size_t refs = 0;
        for (const Ac3dSurface& s : object.surfaces)
            refs += s.refs;
        if (object.surfaces.empty() || refs == 0) {
            out.push_back(false); // a point cloud: one material, no faces
        } else {
            std::vector<unsigned> faces(std::max<std::size_t>(fileMaterials, 1), 0);
            std::vector<bool> twoSided(faces.size(), false);
            for (const Ac3dSurface& s : object.surfaces) {
                const std::size_t m = s.material < faces.size() ? s.material : 0;
                faces[m] += facesOf(s);
                const unsigned type = s.flags & 0xfu;
                if ((s.flags & 0x20u) && type != 1 && type != 2) twoSided[m] = true;
            }
            for (std::size_t m = 0; m < faces.size(); ++m)
                if (faces[m] != 0) out.push_back(twoSided[m]);
        }
    }
    for (const Ac3dObject& kid : object.kids)
        appendMaterialSides(kid, fileMaterials, out, depth + 1);
}

} // namespace

std::optional<std::vector<bool>> ac3dTwoSidedMaterials(const Ac3dFile& file,
                                                       std::size_t assimpMaterials) {
    std::vector<bool> out;
    for (const Ac3dObject& object : file.objects)
        appendMaterialSides(object, file.materials, out, 0);
    if (out.size() != assimpMaterials) return std::nullopt;
    return out;
}

bool isAc3dPath(const std::filesystem::path& file) {
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext == ".ac" || ext == ".acc" || ext == ".ac3d";
}

} // namespace hlod
