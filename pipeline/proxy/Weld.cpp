// Grid welding with an open-addressing hash table (linear probing), see Weld.h.
#include "pipeline/proxy/Weld.h"

#include <cmath>
#include <cstring>

namespace hlod {

namespace {

constexpr std::uint32_t kUnset = 0xffffffffu;

struct CellKey {
    std::int64_t x, y, z;
    std::uint32_t color;
    bool operator==(const CellKey& o) const {
        return x == o.x && y == o.y && z == o.z && color == o.color;
    }
};

std::uint64_t mix(std::uint64_t h) {
    h ^= h >> 33;
    h *= 0xff51afd7ed558ccdull;
    h ^= h >> 33;
    return h;
}

std::uint64_t hashKey(const CellKey& k) {
    std::uint64_t h = mix(static_cast<std::uint64_t>(k.x) * 0x9E3779B185EBCA87ull);
    h = mix(h ^ (static_cast<std::uint64_t>(k.y) * 0xC2B2AE3D27D4EB4Full));
    h = mix(h ^ (static_cast<std::uint64_t>(k.z) * 0x165667B19E3779F9ull));
    return mix(h ^ k.color);
}

std::int64_t cellOf(float v, double inverseCell) {
    // Clamp so absurd coordinates cannot overflow the integer conversion.
    const double q = std::floor(static_cast<double>(v) * inverseCell);
    return static_cast<std::int64_t>(q < -4e18 ? -4e18 : (q > 4e18 ? 4e18 : q));
}

CellKey keyOf(const ProxyMesh& m, std::uint32_t v, double inverseCell) {
    CellKey k{};
    const glm::vec3& p = m.positions[v];
    if (inverseCell > 0.0) {
        k.x = cellOf(p.x, inverseCell);
        k.y = cellOf(p.y, inverseCell);
        k.z = cellOf(p.z, inverseCell);
    } else {
        // Exact welding: the float bits (with -0 folded onto +0, which compare equal).
        const glm::vec3 q = p + glm::vec3(0.0f);
        std::uint32_t bits[3];
        std::memcpy(bits, &q, sizeof(bits));
        k.x = bits[0];
        k.y = bits[1];
        k.z = bits[2];
    }
    const glm::u8vec4 c = v < m.colors.size() ? m.colors[v] : glm::u8vec4(255);
    k.color = static_cast<std::uint32_t>(c.r) | (static_cast<std::uint32_t>(c.g) << 8) |
              (static_cast<std::uint32_t>(c.b) << 16) | (static_cast<std::uint32_t>(c.a) << 24);
    return k;
}

// Applies `remap` (old vertex -> new vertex, in first-use order) and drops degenerate faces.
void rebuild(ProxyMesh& m, const std::vector<std::uint32_t>& remap,
             const std::vector<std::uint32_t>& representative) {
    ProxyMesh out;
    out.origin = m.origin;
    out.positions.reserve(representative.size());
    out.colors.reserve(representative.size());
    const bool hasColors = m.colors.size() == m.positions.size();
    for (std::uint32_t v : representative) {
        out.positions.push_back(m.positions[v]);
        out.colors.push_back(hasColors ? m.colors[v] : glm::u8vec4(255));
    }
    out.indices.reserve(m.indices.size());
    for (std::size_t t = 0; t + 2 < m.indices.size(); t += 3) {
        const std::uint32_t a = remap[m.indices[t]], b = remap[m.indices[t + 1]],
                            c = remap[m.indices[t + 2]];
        if (a == b || b == c || a == c) continue;
        out.indices.insert(out.indices.end(), {a, b, c});
    }
    m = std::move(out);
}

// Open-addressing table from a key to the first representative filed under it; further
// representatives of the same key are chained through `next`.
class KeyTable {
public:
    explicit KeyTable(std::size_t expected) {
        std::size_t buckets = 16;
        while (buckets < 2 * expected)
            buckets *= 2;
        slots_.assign(buckets, kUnset);
    }
    // Head of the chain for `key` (kUnset when none).
    std::uint32_t head(const CellKey& key) const {
        for (std::size_t s = hashKey(key) & (slots_.size() - 1);;
             s = (s + 1) & (slots_.size() - 1)) {
            if (slots_[s] == kUnset) return kUnset;
            if (keys_[slots_[s]] == key) return heads_[slots_[s]];
        }
    }
    void add(const CellKey& key, std::uint32_t rep, std::vector<std::uint32_t>& next) {
        std::size_t s = hashKey(key) & (slots_.size() - 1);
        while (slots_[s] != kUnset && !(keys_[slots_[s]] == key))
            s = (s + 1) & (slots_.size() - 1);
        if (slots_[s] == kUnset) {
            slots_[s] = static_cast<std::uint32_t>(keys_.size());
            keys_.push_back(key);
            heads_.push_back(kUnset);
        }
        next[rep] = heads_[slots_[s]];
        heads_[slots_[s]] = rep;
    }

private:
    std::vector<std::uint32_t> slots_;
    std::vector<CellKey> keys_;
    std::vector<std::uint32_t> heads_;
};

} // namespace

void weldVertices(ProxyMesh& mesh, float tolerance) {
    weldCorners(mesh, WeldOptions{tolerance, true, false});
}

namespace {

// The grid probe of weldCorners: the first representative within `tolerance` of p (on every
// axis) filed under a cell around p with `colorKey`, that `accept` agrees to; kUnset if none.
template <class Accept>
std::uint32_t findTwin(const KeyTable& table, const std::vector<std::uint32_t>& next,
                       const std::vector<glm::vec3>& repPosition, const glm::vec3& p,
                       float tolerance, double inverseCell, std::uint32_t colorKey,
                       Accept&& accept) {
    const glm::vec3 lo = p - glm::vec3(tolerance), hi = p + glm::vec3(tolerance);
    const std::int64_t x0 = cellOf(lo.x, inverseCell), x1 = cellOf(hi.x, inverseCell);
    const std::int64_t y0 = cellOf(lo.y, inverseCell), y1 = cellOf(hi.y, inverseCell);
    const std::int64_t z0 = cellOf(lo.z, inverseCell), z1 = cellOf(hi.z, inverseCell);
    for (std::int64_t x = x0; x <= x1; ++x) {
        for (std::int64_t y = y0; y <= y1; ++y) {
            for (std::int64_t z = z0; z <= z1; ++z) {
                for (std::uint32_t r = table.head(CellKey{x, y, z, colorKey}); r != kUnset;
                     r = next[r]) {
                    const glm::vec3 delta = glm::abs(repPosition[r] - p);
                    if (delta.x <= tolerance && delta.y <= tolerance && delta.z <= tolerance &&
                        accept(r))
                        return r;
                }
            }
        }
    }
    return kUnset;
}

} // namespace

void weldCorners(ProxyMesh& mesh, const WeldOptions& options) {
    const std::size_t n = mesh.positions.size();
    if (n == 0) return;
    const float tolerance = options.tolerance;
    // Cells four times the tolerance wide: the vertices within `tolerance` of a point lie in at
    // most two cells per axis (a vertex near a cell wall still finds its twin in the next
    // cell), and in one cell for the half of the positions away from the walls, so a vertex
    // probes 1.5^3 = 3.4 cells on average (2^3 = 8 with cells twice the tolerance wide).
    const double inverseCell = tolerance > 0.0f ? 0.25 / static_cast<double>(tolerance) : 0.0;
    KeyTable table(n);
    std::vector<std::uint32_t> representative, next;
    std::vector<glm::vec3> repPosition, repNormal;
    representative.reserve(n);
    next.reserve(n);
    // Corner-level remap; without sides every corner of a vertex welds alike (one lookup).
    std::vector<std::uint32_t> vertexRep(n, kUnset), cornerRep(mesh.indices.size());
    for (std::size_t i = 0; i < mesh.indices.size(); ++i) {
        const std::uint32_t v = mesh.indices[i];
        if (!options.sides && vertexRep[v] != kUnset) {
            cornerRep[i] = vertexRep[v];
            continue;
        }
        CellKey key = keyOf(mesh, v, inverseCell);
        if (!options.byColour) key.color = 0;
        glm::vec3 side(0.0f);
        if (options.sides) {
            const std::size_t t = i - i % 3;
            if (t + 2 < mesh.indices.size()) {
                const glm::vec3 &a = mesh.positions[mesh.indices[t]],
                                &b = mesh.positions[mesh.indices[t + 1]],
                                &c = mesh.positions[mesh.indices[t + 2]];
                const glm::vec3 f = glm::cross(b - a, c - a);
                const float len = glm::length(f);
                if (len > 0.0f) side = f / len;
            }
        }
        // Two sides of a sheet: faces more than 120 degrees apart keep their own vertices.
        auto sameSide = [&](std::uint32_t r) { return glm::dot(repNormal[r], side) > -0.5f; };
        std::uint32_t found = kUnset;
        const glm::vec3& p = mesh.positions[v];
        if (inverseCell == 0.0) {
            for (std::uint32_t r = table.head(key); r != kUnset && found == kUnset; r = next[r])
                if (!options.sides || sameSide(r)) found = r;
        } else {
            found = findTwin(table, next, repPosition, p, tolerance, inverseCell, key.color,
                             [&](std::uint32_t r) { return !options.sides || sameSide(r); });
        }
        if (found == kUnset) {
            found = static_cast<std::uint32_t>(representative.size());
            representative.push_back(v);
            repPosition.push_back(p);
            repNormal.push_back(side);
            next.push_back(kUnset);
            table.add(key, found, next);
        }
        cornerRep[i] = found;
        vertexRep[v] = found;
    }
    ProxyMesh out;
    out.origin = mesh.origin;
    out.positions = std::move(repPosition);
    const bool hasColors = mesh.colors.size() == mesh.positions.size();
    out.colors.reserve(representative.size());
    for (std::uint32_t v : representative)
        out.colors.push_back(hasColors ? mesh.colors[v] : glm::u8vec4(255));
    out.indices.reserve(mesh.indices.size());
    for (std::size_t t = 0; t + 2 < cornerRep.size(); t += 3) {
        const std::uint32_t a = cornerRep[t], b = cornerRep[t + 1], c = cornerRep[t + 2];
        if (a == b || b == c || a == c) continue;
        out.indices.insert(out.indices.end(), {a, b, c});
    }
    mesh = std::move(out);
}

void compactMesh(ProxyMesh& mesh) {
    // Degenerate triangles go first so their corners do not keep otherwise unused vertices.
    std::vector<std::uint32_t> indices;
    indices.reserve(mesh.indices.size());
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const std::uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
        if (a == b || b == c || a == c) continue;
        indices.insert(indices.end(), {a, b, c});
    }
    mesh.indices = std::move(indices);
    std::vector<std::uint32_t> remap(mesh.positions.size(), kUnset);
    std::vector<std::uint32_t> representative;
    representative.reserve(mesh.positions.size());
    for (std::uint32_t v : mesh.indices) {
        if (remap[v] != kUnset) continue;
        remap[v] = static_cast<std::uint32_t>(representative.size());
        representative.push_back(v);
    }
    std::vector<glm::vec3> normals;
    const bool hasNormals = mesh.normals.size() == mesh.positions.size();
    if (hasNormals) {
        normals.reserve(representative.size());
        for (std::uint32_t v : representative)
            normals.push_back(mesh.normals[v]);
    }
    rebuild(mesh, remap, representative);
    if (hasNormals) mesh.normals = std::move(normals);
}

} // namespace hlod
