// Edge collapse simplification with quadrics, feature edges and locks, see QuadricSimplify.h.
#include "pipeline/proxy/QuadricSimplify.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <tuple>
#include <unordered_map>

#include "pipeline/proxy/CollapseTopology.h"
#include "pipeline/proxy/Quadric.h"
#include "pipeline/proxy/SurfaceQuery.h"

namespace hlod {

namespace {

constexpr std::uint32_t kDead = 0xffffffffu;
// Face planes weigh the square root of their area, so errors scale linearly with size (as
// meshoptimizer weighs them: it keeps silhouettes better than area weights); constraint planes
// of feature edges weigh this much per metre of edge length, so that sliding a vertex off a
// feature line costs more than leaving a face of similar size.
constexpr double kFeatureWeight = 10.0;
// Two faces whose normals are further apart than this (cosine) meet at a fold: a sheet's rim.
constexpr double kFoldCosine = -0.766; // 140 degrees
// A remaining face may turn by at most this much (cosine) in one collapse.
constexpr double kMinTurnCosine = 0.2; // 78 degrees
constexpr int kMaxPasses = 200;

enum class Kind : std::uint8_t { Interior, Feature, Fixed, Locked };

// One triangle corner's edge, stored from its smaller to its larger vertex.
struct HalfEdge {
    std::uint32_t lo, hi, tri;
    bool forward; // the triangle runs lo -> hi
};

// A collapse: `from` goes into `to`, which moves to `at`.
struct Candidate {
    double cost;
    std::uint32_t from, to;
    glm::vec3 at;
};

class Simplifier {
public:
    Simplifier(std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices,
               std::span<const std::uint8_t> locked, double deviationLimit)
        : input_(positions), pos_(positions.begin(), positions.end()), locked_(locked),
          tris_(indices.begin(), indices.end()), quadrics_(positions.size()),
          rep_(positions.size()), bounded_(deviationLimit > 0.0) {
        for (std::uint32_t v = 0; v < rep_.size(); ++v)
            rep_[v] = v;
        for (std::size_t t = 0; t < tris_.size() / 3; ++t)
            addFaceQuadric(t);
        buildAdjacency();
        buildEdges();
        addFeatureQuadrics();
        if (bounded_) {
            limit_ = static_cast<float>(deviationLimit);
            limit2_ = limit_ * limit_;
            original_.reset(positions, indices,
                            static_cast<float>(deviationLimit) * (1.0f - surface::kSlackFraction));
            coverage_ = std::make_unique<surface::Coverage>(
                original_, static_cast<float>(deviationLimit) * surface::kSlackFraction);
            // A vertex at its input position lies on the input triangles it is a corner of.
            nearOf_.assign(positions.size(), surface::kNoTriangle);
            for (std::size_t i = 0; i < indices.size(); ++i)
                if (nearOf_[indices[i]] == surface::kNoTriangle)
                    nearOf_[indices[i]] = static_cast<std::uint32_t>(i / 3);
            makeSamples();
        }
    }

    // Bounded mode continued from `start`, a simplification of the input (positions, indices)
    // over the input's vertex numbering, certified against the input.
    Simplifier(std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices,
               const QuadricStart& start, double deviationLimit)
        : input_(positions), pos_(start.positions.begin(), start.positions.end()),
          tris_(start.indices.begin(), start.indices.end()), quadrics_(positions.size()),
          rep_(start.representative.begin(), start.representative.end()), bounded_(true) {
        {
            // Freed before the grids below are built (88 bytes per input vertex at the bake's
            // peak otherwise).
            std::vector<Quadric> ownQuadrics(positions.size());
            addQuadrics(positions, indices, ownQuadrics);
            for (std::uint32_t v = 0; v < ownQuadrics.size(); ++v)
                quadrics_[rep_[v]].add(ownQuadrics[v]);
        }
        buildAdjacency();
        buildEdges();
        limit_ = static_cast<float>(deviationLimit);
        limit2_ = limit_ * limit_;
        // A vertex still at its input position lies on the input triangles it is a corner of;
        // a moved one is located when first needed.
        nearOf_.assign(positions.size(), surface::kNoTriangle);
        for (std::size_t i = 0; i < indices.size(); ++i) {
            const std::uint32_t v = indices[i];
            if (nearOf_[v] == surface::kNoTriangle && pos_[v] == positions[v])
                nearOf_[v] = static_cast<std::uint32_t>(i / 3);
        }
        {
            // The input's samples, each owned by a face of the start within the limit of it
            // (the start lies within the limit both ways; one the search misses stays unowned
            // and the final check (BoundedSimplify.h) puts its input triangle back if it must).
            // The start's grid is gone before the input's is built: they never coexist.
            owned_.assign(tris_.size() / 3, {});
            surface::NearSurface current;
            current.reset(pos_, tris_, limit_);
            auto own = [&](const glm::vec3& at) {
                if (!current.near(at)) return;
                owned_[current.lastFound()].push_back(at);
            };
            std::vector<std::uint8_t> seen(positions.size(), 0);
            for (std::size_t t = 0; t < indices.size() / 3; ++t) {
                const std::uint32_t* c = &indices[3 * t];
                for (int k = 0; k < 3; ++k) {
                    if (seen[c[k]]) continue;
                    seen[c[k]] = 1;
                    own(positions[c[k]]);
                }
                forEachSample(positions[c[0]], positions[c[1]], positions[c[2]], own);
            }
        }
        original_.reset(positions, indices, limit_ * (1.0f - surface::kSlackFraction));
        coverage_ =
            std::make_unique<surface::Coverage>(original_, limit_ * surface::kSlackFraction);
    }

    void run(double maxError) {
        const double limit = maxError * maxError;
        changed_.assign(pos_.size(), 0);
        for (int pass = 0; pass < kMaxPasses; ++pass) {
            if (pass > 0) {
                buildAdjacency();
                buildEdges();
            }
            classify();
            if (collapsePass(limit) == 0) break;
            compact();
        }
    }

    QuadricSimplifyResult result() {
        compact();
        QuadricSimplifyResult out;
        out.indices = std::move(tris_);
        resolveRepresentatives(rep_);
        out.representative = std::move(rep_);
        out.positions = std::move(pos_);
        return out;
    }

private:
    glm::dvec3 p(std::uint32_t v) const { return glm::dvec3(pos_[v]); }

    glm::dvec3 faceNormal(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) const {
        return glm::cross(b - a, c - a);
    }
    glm::dvec3 triNormal(std::uint32_t t) const {
        return faceNormal(p(tris_[3 * t]), p(tris_[3 * t + 1]), p(tris_[3 * t + 2]));
    }

    void addFaceQuadric(std::size_t t) {
        const std::uint32_t a = tris_[3 * t], b = tris_[3 * t + 1], c = tris_[3 * t + 2];
        const glm::dvec3 n = triNormal(static_cast<std::uint32_t>(t));
        const double len = glm::length(n);
        if (!(len > 0.0)) return;
        const glm::dvec3 unit = n / len;
        const double d = -glm::dot(unit, p(a));
        for (std::uint32_t v : {a, b, c})
            quadrics_[v].addPlane(unit, d, std::sqrt(0.5 * len));
    }

    // Vertex -> triangles (CSR) of the current triangles.
    void buildAdjacency() {
        offsets_.assign(pos_.size() + 1, 0);
        for (std::uint32_t v : tris_)
            ++offsets_[v + 1];
        for (std::size_t i = 1; i < offsets_.size(); ++i)
            offsets_[i] += offsets_[i - 1];
        vertexTris_.resize(tris_.size());
        fill_.assign(offsets_.begin(), offsets_.end() - 1);
        for (std::size_t i = 0; i < tris_.size(); ++i)
            vertexTris_[fill_[tris_[i]]++] = static_cast<std::uint32_t>(i / 3);
    }

    std::span<const std::uint32_t> trianglesOf(std::uint32_t v) const {
        return {vertexTris_.data() + offsets_[v], offsets_[v + 1] - offsets_[v]};
    }

    // Half-edges sorted by (lo, hi, tri): bucketed by lo (counting sort, in triangle order),
    // then each bucket sorted by (hi, tri). Equal keys come only from one degenerate triangle
    // (identical entries but for `forward`), which every use treats alike.
    void buildEdges() {
        edgeStart_.assign(pos_.size() + 1, 0);
        const std::size_t triangles = tris_.size() / 3;
        for (std::size_t t = 0; t < triangles; ++t) {
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t a = tris_[3 * t + k], b = tris_[3 * t + (k + 1) % 3];
                ++edgeStart_[std::min(a, b) + 1];
            }
        }
        for (std::size_t i = 1; i < edgeStart_.size(); ++i)
            edgeStart_[i] += edgeStart_[i - 1];
        edges_.resize(3 * triangles);
        fill_.assign(edgeStart_.begin(), edgeStart_.end() - 1);
        for (std::size_t t = 0; t < triangles; ++t) {
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t a = tris_[3 * t + k], b = tris_[3 * t + (k + 1) % 3];
                edges_[fill_[std::min(a, b)]++] =
                    HalfEdge{std::min(a, b), std::max(a, b), static_cast<std::uint32_t>(t), a < b};
            }
        }
        for (std::size_t v = 0; v + 1 < edgeStart_.size(); ++v) {
            const auto first = edges_.begin() + edgeStart_[v],
                       last = edges_.begin() + edgeStart_[v + 1];
            if (last - first < 2) continue;
            // Insertion sort: buckets are a vertex's edges, a handful.
            for (auto i = first + 1; i < last; ++i) {
                const HalfEdge e = *i;
                auto j = i;
                for (; j > first && std::tie(e.hi, e.tri) < std::tie((j - 1)->hi, (j - 1)->tri);
                     --j)
                    *j = *(j - 1);
                *j = e;
            }
        }
    }

    // Whether the edge group edges_[first, last) is a feature (see the header).
    bool isFeature(std::size_t first, std::size_t last) const {
        const std::size_t faces = last - first;
        if (faces != 2) return true;
        const HalfEdge &e0 = edges_[first], &e1 = edges_[first + 1];
        if (e0.forward == e1.forward) return true; // inconsistently oriented
        const glm::dvec3 n0 = triNormal(e0.tri), n1 = triNormal(e1.tri);
        const double l0 = glm::length(n0), l1 = glm::length(n1);
        if (!(l0 > 0.0 && l1 > 0.0)) return false;
        return glm::dot(n0, n1) < kFoldCosine * l0 * l1;
    }

    template <class F> void forEachEdge(F&& visit) const {
        for (std::size_t first = 0; first < edges_.size();) {
            std::size_t last = first + 1;
            while (last < edges_.size() && edges_[last].lo == edges_[first].lo &&
                   edges_[last].hi == edges_[first].hi)
                ++last;
            visit(first, last);
            first = last;
        }
    }

    // Constraint planes along the input's feature edges (once, on the input mesh).
    void addFeatureQuadrics() {
        forEachEdge([&](std::size_t first, std::size_t last) {
            if (!isFeature(first, last)) return;
            const std::uint32_t a = edges_[first].lo, b = edges_[first].hi;
            const glm::dvec3 e = p(b) - p(a);
            const double len = glm::length(e);
            if (!(len > 0.0)) return;
            for (std::size_t i = first; i < last; ++i) {
                const glm::dvec3 n = glm::cross(e, triNormal(edges_[i].tri));
                const double nl = glm::length(n);
                if (!(nl > 0.0)) continue;
                const glm::dvec3 unit = n / nl;
                const double d = -glm::dot(unit, p(a));
                quadrics_[a].addPlane(unit, d, kFeatureWeight * len);
                quadrics_[b].addPlane(unit, d, kFeatureWeight * len);
            }
        });
    }

    void classify() {
        featureEdges_.assign(pos_.size(), 0);
        // Bounded mode tells only locked vertices from the others (mayMove).
        if (!bounded_)
            forEachEdge([&](std::size_t first, std::size_t last) {
                if (!isFeature(first, last)) return;
                for (std::uint32_t v : {edges_[first].lo, edges_[first].hi})
                    featureEdges_[v] =
                        static_cast<std::uint8_t>(std::min(featureEdges_[v] + 1, 255));
            });
        kinds_.resize(pos_.size());
        for (std::uint32_t v = 0; v < pos_.size(); ++v) {
            const std::uint8_t f = featureEdges_[v];
            const bool lock = v < locked_.size() && locked_[v] != 0;
            kinds_[v] = lock               ? Kind::Locked
                        : f != 0 && f != 2 ? Kind::Fixed
                        : f == 2           ? Kind::Feature
                                           : Kind::Interior;
        }
    }

    bool mayMove(std::uint32_t u, bool featureEdge) const {
        if (bounded_) return kinds_[u] != Kind::Locked; // every collapse is measured instead
        return kinds_[u] == Kind::Interior || (kinds_[u] == Kind::Feature && featureEdge);
    }

    // The best collapse of edge (a, b), if any is allowed. Plain mode: half-edge collapses
    // (the kept vertex stays). Bounded mode: the kept vertex moves to the point of least error
    // of both quadrics among the optimum, the midpoint and both ends (a locked vertex stays).
    bool bestCollapse(std::uint32_t a, std::uint32_t b, bool feature, double limit,
                      Candidate& best) const {
        bool any = false;
        best.cost = limit;
        auto consider = [&](std::uint32_t from, std::uint32_t to, const glm::dvec3& at,
                            double cost) {
            if (cost < best.cost || (!any && cost <= best.cost)) {
                best = Candidate{cost, from, to, glm::vec3(at)};
                any = true;
            }
        };
        const bool moveA = mayMove(a, feature), moveB = mayMove(b, feature);
        if (!bounded_) {
            if (moveA) consider(a, b, p(b), quadrics_[a].error(p(b)));
            if (moveB) consider(b, a, p(a), quadrics_[b].error(p(a)));
            return any;
        }
        if (!moveA && !moveB) return false;
        Quadric q = quadrics_[a];
        q.add(quadrics_[b]);
        if (!moveA) { // b goes into a, which stays
            consider(b, a, p(a), q.error(p(a)));
            return any;
        }
        if (!moveB) {
            consider(a, b, p(b), q.error(p(b)));
            return any;
        }
        consider(a, b, p(b), q.error(p(b)));
        consider(b, a, p(a), q.error(p(a)));
        const glm::dvec3 mid = (p(a) + p(b)) * 0.5;
        consider(a, b, mid, q.error(mid));
        glm::dvec3 opt;
        // The optimum, when the planes pin it down and it stays near the edge.
        if (q.minimum(opt) && glm::length(opt - mid) <= glm::length(p(b) - p(a)))
            consider(a, b, opt, q.error(opt));
        return any;
    }

    std::size_t collapsePass(double limit) {
        std::vector<Candidate> candidates;
        forEachEdge([&](std::size_t first, std::size_t last) {
            Candidate c;
            // Bounded mode does not look at features (mayMove).
            const bool feature = !bounded_ && isFeature(first, last);
            if (bestCollapse(edges_[first].lo, edges_[first].hi, feature, limit, c))
                candidates.push_back(c);
        });
        std::sort(candidates.begin(), candidates.end(), [](const Candidate& x, const Candidate& y) {
            return std::tie(x.cost, x.from, x.to) < std::tie(y.cost, y.from, y.to);
        });
        touched_.assign(pos_.size(), 0);
        std::size_t done = 0;
        // Only the cheaper part of the collapses goes in one pass (the costs of the others go
        // stale as their neighbours move): up to 1.5x the cost of the collapse a third of the
        // way down, once a twelfth of the candidates is done (meshoptimizer's pass goal).
        const double goal = candidates.empty() ? 0.0 : 1.5 * candidates[candidates.size() / 3].cost;
        for (const Candidate& c : candidates) {
            if (c.cost > goal && done * 12 > candidates.size()) break;
            if (touched_[c.from] || touched_[c.to]) continue;
            // The cheapest tests first. In bounded mode every failure is remembered: the
            // collapses left in the late passes are mostly ones that failed before.
            if (bounded_ && failedBefore(c)) continue;
            if (!linkConditionHolds(c.from, c.to) || flipsAFace(c) ||
                (bounded_ && !staysWithinLimit(c))) {
                if (bounded_) failed_[key(c)] = stamp_;
                continue;
            }
            collapse(c);
            ++done;
        }
        return done;
    }

    // Bounded mode: a collapse that failed (the link condition, a flip or the limit) fails
    // again until a face around either end changes: every such change marks both ends with
    // the collapse's stamp (see collapse()), and the tests read nothing else (the link of
    // both ends, the positions of their faces' corners, and the candidate's end point, made
    // from the quadrics and positions of its ends).
    static std::uint64_t key(const Candidate& c) {
        return (static_cast<std::uint64_t>(c.from) << 32) | c.to;
    }
    bool failedBefore(const Candidate& c) const {
        const auto it = failed_.find(key(c));
        return it != failed_.end() && it->second >= changed_[c.from] &&
               it->second >= changed_[c.to];
    }

    void neighbours(std::uint32_t v, std::vector<std::uint32_t>& out) const {
        out.clear();
        for (std::uint32_t t : trianglesOf(v)) {
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t w = tris_[3 * t + k];
                if (w != v && w != kDead) out.push_back(w);
            }
        }
        std::sort(out.begin(), out.end());
        out.erase(std::unique(out.begin(), out.end()), out.end());
    }

    // Every vertex adjacent to both u and v must be the third corner of a face on edge (u, v);
    // otherwise the collapse would pinch the surface (or duplicate a face).
    bool linkConditionHolds(std::uint32_t u, std::uint32_t v) {
        neighbours(u, nu_);
        neighbours(v, nv_);
        opposite_.clear();
        for (std::uint32_t t : trianglesOf(u)) {
            const std::uint32_t* c = &tris_[3 * t];
            if (c[0] != v && c[1] != v && c[2] != v) continue;
            for (int k = 0; k < 3; ++k)
                if (c[k] != u && c[k] != v) opposite_.push_back(c[k]);
        }
        return hlod::linkConditionHolds(nu_, nv_, opposite_);
    }

    // Calls visit(slot, corners after) for every face around c.from and c.to that survives
    // the collapse (faces on the edge itself die).
    template <class F> void forEachReshaped(const Candidate& c, F&& visit) const {
        for (std::uint32_t end : {c.from, c.to}) {
            for (std::uint32_t t : trianglesOf(end)) {
                const std::uint32_t* k = &tris_[3 * t];
                if (k[0] == kDead) continue;
                const bool hasFrom = k[0] == c.from || k[1] == c.from || k[2] == c.from;
                const bool hasTo = k[0] == c.to || k[1] == c.to || k[2] == c.to;
                if (hasFrom && hasTo) continue;
                if (end == c.to && hasFrom) continue; // seen from c.from already
                glm::dvec3 q[3];
                for (int i = 0; i < 3; ++i)
                    q[i] = k[i] == c.from || k[i] == c.to ? glm::dvec3(c.at) : p(k[i]);
                visit(t, q);
            }
        }
    }

    bool flipsAFace(const Candidate& c) const {
        bool flips = false;
        forEachReshaped(c, [&](std::uint32_t t, const glm::dvec3* q) {
            if (flips) return;
            const glm::dvec3 before = triNormal(t), after = faceNormal(q[0], q[1], q[2]);
            const double lb = glm::length(before), la = glm::length(after);
            if (!(lb > 0.0)) return; // a degenerate face has no direction to keep
            if (!(glm::dot(before, after) > kMinTurnCosine * lb * la)) flips = true;
        });
        return flips;
    }

    void collapse(const Candidate& c) {
        ++stamp_;
        for (std::uint32_t end : {c.from, c.to}) {
            for (std::uint32_t t : trianglesOf(end)) {
                std::uint32_t* k = &tris_[3 * t];
                if (k[0] == kDead) continue;
                for (int i = 0; i < 3; ++i) {
                    if (k[i] == c.from) k[i] = c.to;
                    touched_[k[i]] = 1;
                }
                if (k[0] == k[1] || k[1] == k[2] || k[0] == k[2]) k[0] = k[1] = k[2] = kDead;
            }
        }
        touched_[c.from] = touched_[c.to] = 1;
        for (std::uint32_t end : {c.from, c.to})
            for (std::uint32_t t : trianglesOf(end))
                if (tris_[3 * t] != kDead)
                    for (int i = 0; i < 3; ++i)
                        changed_[tris_[3 * t + i]] = stamp_;
        changed_[c.from] = changed_[c.to] = stamp_;
        quadrics_[c.to].add(quadrics_[c.from]);
        pos_[c.to] = c.at;
        if (bounded_) nearOf_[c.to] = atNear_; // located at c.at by staysWithinLimit
        rep_[c.from] = c.to;
        if (bounded_) {
            for (std::uint32_t end : {c.from, c.to})
                for (std::uint32_t t : trianglesOf(end))
                    owned_[t].clear();
            for (std::size_t j = 0; j < pending_.size(); ++j) // where staysWithinLimit put them
                owned_[ringSlot_[placedIn_[j]]].push_back(pending_[j]);
        }
    }

    void compact() {
        std::size_t out = 0;
        for (std::size_t i = 0; i < tris_.size(); i += 3) {
            if (tris_[i] == kDead) continue;
            for (int k = 0; k < 3; ++k)
                tris_[out + k] = tris_[i + k];
            if (bounded_ && out != i) owned_[out / 3] = std::move(owned_[i / 3]);
            out += 3;
        }
        tris_.resize(out);
        if (bounded_) owned_.resize(out / 3);
    }

    // Sample points of the input surface, each owned by the triangle nearest to it (at first,
    // its own): every vertex once, and the centroids of a k x k subdivision of each triangle,
    // k = its longest edge over the limit (at most 6), so that long triangles are sampled
    // along their length too.
    void makeSamples() {
        owned_.assign(tris_.size() / 3, {});
        std::vector<std::uint8_t> seen(pos_.size(), 0);
        for (std::size_t t = 0; t < tris_.size() / 3; ++t) {
            const std::uint32_t* c = &tris_[3 * t];
            const glm::vec3 &a = pos_[c[0]], &b = pos_[c[1]], &d = pos_[c[2]];
            for (int k = 0; k < 3; ++k) {
                if (seen[c[k]]) continue;
                seen[c[k]] = 1;
                addSample(pos_[c[k]], t);
            }
            forEachSample(a, b, d, [&](const glm::vec3& at) { addSample(at, t); });
        }
    }

    // The centroids of a k x k subdivision of triangle abc, k = its longest edge over the limit
    // (1 to 6): points about a limit apart across the triangle.
    template <class F>
    void forEachSample(const glm::vec3& a, const glm::vec3& b, const glm::vec3& d,
                       F&& visit) const {
        const float longest = std::sqrt(
            std::max({glm::dot(b - a, b - a), glm::dot(d - b, d - b), glm::dot(a - d, a - d)}));
        const int n = std::clamp(static_cast<int>(std::ceil(longest / limit_)), 1, 6);
        for (int i = 0; i < n; ++i) {
            for (int j = 0; i + j < n; ++j) {
                // Centroids of the upward sub-triangles, and of the downward ones between.
                visit(a + (b - a) * ((i + 1.0f / 3) / n) + (d - a) * ((j + 1.0f / 3) / n));
                if (i + j + 1 < n)
                    visit(a + (b - a) * ((i + 2.0f / 3) / n) + (d - a) * ((j + 2.0f / 3) / n));
            }
        }
    }

    // Places the pending samples [first, last) that lie within the limit of ring face `i`;
    // the others go to unplaced_.
    void placeBlock(const surface::Triangle& face, std::uint32_t i, std::uint32_t first,
                    std::uint32_t last) {
        for (std::uint32_t j = first; j < last; j += 4) {
            const std::uint32_t n = std::min<std::uint32_t>(4, last - j);
            surface::Points4 block;
            for (std::uint32_t k = 0; k < 4; ++k) {
                const glm::vec3& q = pending_[j + std::min(k, n - 1)];
                block.x[k] = q.x, block.y[k] = q.y, block.z[k] = q.z;
            }
            const unsigned inside = surface::withinMask4(face, block, limit2_);
            for (std::uint32_t k = 0; k < n; ++k) {
                if (inside & (1u << k))
                    placedIn_[j + k] = i;
                else
                    unplaced_.push_back(j + k);
            }
        }
    }

    void addSample(const glm::vec3& at, std::size_t t) { owned_[t].push_back(at); }

    // Bounded mode: whether the mesh stays within the limit of the input both ways after the
    // collapse. The reshaped faces must lie within the limit of the input surface (certified,
    // SurfaceQuery.h Coverage), and every sample owned by a face around either end must lie
    // within the limit of a reshaped face afterwards; pending_ and placedIn_ say where each sample
    // goes.
    bool staysWithinLimit(const Candidate& c) {
        ring_.clear();
        ringSlot_.clear();
        ringCorners_.clear();
        forEachReshaped(c, [&](std::uint32_t t, const glm::dvec3* q) {
            ring_.push_back(
                surface::makeTriangle(glm::vec3(q[0]), glm::vec3(q[1]), glm::vec3(q[2])));
            ringSlot_.push_back(t);
            // Corners by vertex after the collapse (c.from's becomes c.to's, at c.at).
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t v = tris_[3 * t + k];
                ringCorners_.push_back(v == c.from ? c.to : v);
            }
        });

        // Each sample stays with its face when the face's new shape holds it (most do: a
        // collapse moves one corner), else goes to the first reshaped face (in ring order) it
        // lies within the limit of: run face by face over the samples still unplaced, four at
        // a time. The faces come in ring order (as forEachReshaped visits them), so the n-th
        // face that survives is ring face n.
        pending_.clear();
        placedIn_.clear();
        unplaced_.clear();
        std::uint32_t home = 0;
        for (std::uint32_t end : {c.from, c.to}) {
            for (std::uint32_t t : trianglesOf(end)) {
                const std::uint32_t* k = &tris_[3 * t];
                if (k[0] == kDead) continue;
                const bool hasFrom = k[0] == c.from || k[1] == c.from || k[2] == c.from;
                const bool hasTo = k[0] == c.to || k[1] == c.to || k[2] == c.to;
                // A face of c.to that holds c.from too was seen from c.from.
                if (end == c.to && hasFrom) continue;
                const auto first = static_cast<std::uint32_t>(pending_.size());
                pending_.insert(pending_.end(), owned_[t].begin(), owned_[t].end());
                placedIn_.resize(pending_.size(), 0);
                if (hasFrom && hasTo) { // dies with the edge
                    for (std::uint32_t j = first; j < pending_.size(); ++j)
                        unplaced_.push_back(j);
                    continue;
                }
                placeBlock(ring_[home], home, first, static_cast<std::uint32_t>(pending_.size()));
                ++home;
            }
        }
        for (std::uint32_t i = 0; i < ring_.size() && !unplaced_.empty(); ++i) {
            std::size_t kept = 0;
            for (std::size_t j = 0; j < unplaced_.size(); j += 4) {
                const std::size_t n = std::min<std::size_t>(4, unplaced_.size() - j);
                surface::Points4 block;
                for (std::size_t k = 0; k < 4; ++k) {
                    const glm::vec3& q = pending_[unplaced_[j + std::min(k, n - 1)]];
                    block.x[k] = q.x, block.y[k] = q.y, block.z[k] = q.z;
                }
                const unsigned inside = surface::withinMask4(ring_[i], block, limit2_);
                for (std::size_t k = 0; k < n; ++k) {
                    const std::uint32_t u = unplaced_[j + k];
                    if (inside & (1u << k))
                        placedIn_[u] = i;
                    else
                        unplaced_[kept++] = u;
                }
            }
            unplaced_.resize(kept);
        }
        if (!unplaced_.empty()) return false;
        // The reshaped faces within the limit of the input, certified (SurfaceQuery.h
        // Coverage): every face the result holds was either left as it was in the input or
        // certified when it took its last shape. Corners that did not move keep the input
        // triangle found near them (nearOf_); the moved one is located once for the ring.
        glm::vec3 failAt;
        atNear_ = surface::kNoTriangle;
        for (std::size_t i = 0; i < ring_.size(); ++i) {
            const surface::Triangle& tri = ring_[i];
            const glm::vec3 corner[3] = {tri.a, tri.b, tri.c};
            std::uint32_t near[3];
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t v = ringCorners_[3 * i + k];
                near[k] = v == c.to ? atNear_ : nearOf_[v];
            }
            const bool covered = coverage_->covers(corner, near, failAt);
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t v = ringCorners_[3 * i + k];
                (v == c.to ? atNear_ : nearOf_[v]) = near[k];
            }
            if (!covered) return false;
        }
        return true;
    }

    std::span<const glm::vec3> input_;
    std::vector<glm::vec3> pos_;
    std::span<const std::uint8_t> locked_;
    std::vector<std::uint32_t> tris_;
    std::vector<Quadric> quadrics_;
    std::vector<std::uint32_t> rep_;
    std::vector<std::uint32_t> offsets_, vertexTris_, fill_, edgeStart_;
    std::vector<HalfEdge> edges_;
    std::vector<std::uint8_t> featureEdges_, touched_;
    std::vector<Kind> kinds_;
    std::vector<std::uint32_t> nu_, nv_, opposite_;
    // Bounded mode (deviationLimit > 0).
    bool bounded_ = false;
    float limit_ = 0.0f, limit2_ = 0.0f;
    surface::NearSurface original_;
    std::unique_ptr<surface::Coverage> coverage_;
    // Per triangle slot: the input's sample points it holds (kept with it, so a collapse reads
    // its faces' samples in a row).
    std::vector<std::vector<glm::vec3>> owned_;
    std::vector<surface::Triangle> ring_;
    std::vector<std::uint32_t> ringSlot_, ringCorners_;
    // Per vertex: an input triangle within the limit of its current position (kNoTriangle:
    // not known yet); atNear_ the one found for the moving vertex's new position.
    std::vector<std::uint32_t> nearOf_;
    std::uint32_t atNear_ = surface::kNoTriangle;
    // Scratch of staysWithinLimit, read by collapse(): the samples of the faces around both
    // ends, and per sample the ring face it goes to.
    std::vector<glm::vec3> pending_;
    std::vector<std::uint32_t> placedIn_, unplaced_;
    std::uint32_t stamp_ = 0;            // collapses made so far
    std::vector<std::uint32_t> changed_; // per vertex: stamp of its last change
    std::unordered_map<std::uint64_t, std::uint32_t> failed_; // collapse -> stamp it failed at
};

} // namespace

QuadricSimplifyResult simplifyWithQuadrics(std::span<const glm::vec3> positions,
                                           std::span<const std::uint32_t> indices,
                                           std::span<const std::uint8_t> locked, double maxError,
                                           double deviationLimit) {
    Simplifier s(positions, indices, locked, deviationLimit);
    s.run(maxError);
    return s.result();
}

QuadricSimplifyResult simplifyWithQuadricsFrom(std::span<const glm::vec3> positions,
                                               std::span<const std::uint32_t> indices,
                                               const QuadricStart& start, double maxError,
                                               double deviationLimit) {
    Simplifier s(positions, indices, start, deviationLimit);
    s.run(maxError);
    return s.result();
}

} // namespace hlod
