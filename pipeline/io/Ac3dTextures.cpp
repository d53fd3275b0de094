// A structural AC3D reader that keeps only the object tree, names and first texture lines, see
// Ac3dTextures.h. Vertex and surface blocks are skipped by their declared counts.
#include "pipeline/io/Ac3dTextures.h"

#include <algorithm>
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
    bool readObjects(std::vector<Ac3dObject>& out, std::size_t count, bool topLevel, int depth) {
        if (depth > 1000) return false;
        std::string line;
        while ((topLevel || out.size() < count) && next(line)) {
            if (line.rfind("OBJECT", 0) != 0) {
                if (topLevel) continue; // MATERIAL lines and the header
                return false;
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

    bool skipSurfaces(std::size_t n) {
        std::string line;
        for (std::size_t s = 0; s < n; ++s) {
            // SURF, optional mat, refs M: read up to the refs line.
            while (true) {
                if (!next(line)) return false;
                if (line.rfind("refs", 0) == 0) break;
                if (line.rfind("SURF", 0) != 0 && line.rfind("mat", 0) != 0) return false;
            }
            std::istringstream ls(line.substr(4));
            std::size_t refs = 0;
            if (!(ls >> refs) || !skipLines(refs)) return false;
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
            } else if (token == "numsurf") {
                if (!(ls >> n) || !skipSurfaces(n)) return false;
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

std::optional<std::vector<Ac3dObject>> parseAc3dObjects(const std::string& text) {
    if (text.rfind("AC3D", 0) != 0) return std::nullopt;
    Parser parser(text);
    std::vector<Ac3dObject> objects;
    if (!parser.readObjects(objects, 0, true, 0)) return std::nullopt;
    return objects;
}

std::optional<std::vector<Ac3dObject>> readAc3dObjects(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return std::nullopt;
    std::ostringstream text;
    text << in.rdbuf();
    return parseAc3dObjects(text.str());
}

bool isAc3dPath(const std::filesystem::path& file) {
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext == ".ac" || ext == ".acc" || ext == ".ac3d";
}

} // namespace hlod
