// Edge collapses in a priority queue, each certified by successive mapping, see
// CertifiedSimplify.h.
#include "pipeline/proxy/CertifiedSimplify.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <queue>
#include <tuple>

#include "pipeline/proxy/CollapseTopology.h"
#include "pipeline/proxy/MappingBound.h"
#include "pipeline/proxy/Quadric.h"

namespace hlod {

namespace {

constexpr std::uint32_t kDead = 0xffffffffu;
constexpr std::uint32_t kEnd = 0xffffffffu;
// A remaining face may turn by at most this much (cosine) in one collapse.
constexpr double kMinTurnCosine = 0.2; // 78 degrees

// How the faces around a vertex are arranged.
enum class Shape : std::uint8_t { Interior, Border, Complex };

struct Ring {
    Shape shape = Shape::Complex;
    std::uint32_t borderOut = kEnd, borderIn = kEnd; // border neighbours (Border only)
};

// A collapse: `from` and `to` become one vertex, which keeps the number `to`, at `at`; `from`
// is first placed at `fromAt` (its position, or its position moved onto its border).
struct Candidate {
    double cost;
    std::uint32_t from, to;
    glm::vec3 at, fromAt;
};

class Simplifier {
public:
    Simplifier(std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices,
               std::span<const float> vertexBounds, double limit)
        : pos_(positions.begin(), positions.end()), tris_(indices.begin(), indices.end()),
          quadrics_(positions.size()), rep_(positions.size()), limit_(static_cast<float>(limit)),
          quadricLimit_(limit * limit) {
        bound_.assign(pos_.size(), 0.0f);
        if (vertexBounds.size() == pos_.size())
            bound_.assign(vertexBounds.begin(), vertexBounds.end());
        for (std::uint32_t v = 0; v < rep_.size(); ++v)
            rep_[v] = v;
        alive_.assign(pos_.size(), 0);
        for (std::uint32_t v : tris_)
            alive_[v] = 1;
        buildCornerLists();
        addQuadrics(pos_, tris_, quadrics_);
        stamp_.assign(pos_.size(), 0);
        best_.assign(pos_.size(), Best{});
    }

    std::size_t run() {
        for (std::uint32_t v = 0; v < pos_.size(); ++v)
            if (alive_[v]) rescore(v);
        while (!heap_.empty()) {
            const auto [cost, v, stamp] = heap_.top();
            heap_.pop();
            if (!alive_[v] || stamp != stamp_[v]) continue;
            tryVertex(v);
        }
        return collapses_;
    }

    CertifiedSimplifyResult result() {
        CertifiedSimplifyResult out;
        out.collapses = collapses_;
        for (std::size_t f = 0; f < tris_.size() / 3; ++f) {
            if (tris_[3 * f] == kDead) continue;
            out.indices.insert(out.indices.end(), &tris_[3 * f], &tris_[3 * f] + 3);
        }
        resolveRepresentatives(rep_);
        out.positions = std::move(pos_);
        out.vertexBounds = std::move(bound_);
        out.representative = std::move(rep_);
        return out;
    }

private:
    struct Best {
        double cost = INFINITY;
        std::uint32_t other = kEnd;
    };
    using Entry = std::tuple<double, std::uint32_t, std::uint32_t>; // cost, vertex, stamp

    // Corner lists: every corner 3f + k is in the list of its vertex; corners of dead faces are
    // unlinked lazily as lists are walked.
    void buildCornerLists() {
        head_.assign(pos_.size(), kEnd);
        tail_.assign(pos_.size(), kEnd);
        next_.assign(tris_.size(), kEnd);
        for (std::uint32_t c = 0; c < tris_.size(); ++c) {
            const std::uint32_t v = tris_[c];
            if (head_[v] == kEnd)
                head_[v] = c;
            else
                next_[tail_[v]] = c;
            tail_[v] = c;
        }
    }

    bool faceAlive(std::uint32_t f) const { return tris_[3 * f] != kDead; }

    // Faces around v, in list order; unlinks corners of dead faces on the way.
    void facesOf(std::uint32_t v, std::vector<std::uint32_t>& out) {
        out.clear();
        std::uint32_t prev = kEnd;
        for (std::uint32_t c = head_[v]; c != kEnd;) {
            const std::uint32_t nextCorner = next_[c];
            if (!faceAlive(c / 3)) {
                if (prev == kEnd)
                    head_[v] = nextCorner;
                else
                    next_[prev] = nextCorner;
                if (tail_[v] == c) tail_[v] = prev;
            } else {
                out.push_back(c / 3);
                prev = c;
            }
            c = nextCorner;
        }
    }

    // The other two corners of face f seen from its corner v, in winding order (v -> a -> b).
    void others(std::uint32_t f, std::uint32_t v, std::uint32_t& a, std::uint32_t& b) const {
        const std::uint32_t* t = &tris_[3 * f];
        const int k = t[0] == v ? 0 : t[1] == v ? 1 : 2;
        a = t[(k + 1) % 3];
        b = t[(k + 2) % 3];
    }

    // The shape of v's faces: one closed fan (interior), one open fan (border), or anything
    // else. Each neighbour of an interior vertex is reached once by an edge out of v and once by
    // an edge into v.
    Ring ringOf(std::uint32_t v) {
        facesOf(v, ringFaces_);
        outs_.clear();
        ins_.clear();
        for (std::uint32_t f : ringFaces_) {
            std::uint32_t a, b;
            others(f, v, a, b);
            if (a == v || b == v || a == b) return Ring{}; // degenerate face
            outs_.push_back(a);
            ins_.push_back(b);
        }
        std::sort(outs_.begin(), outs_.end());
        std::sort(ins_.begin(), ins_.end());
        if (std::adjacent_find(outs_.begin(), outs_.end()) != outs_.end() ||
            std::adjacent_find(ins_.begin(), ins_.end()) != ins_.end())
            return Ring{};
        Ring r;
        std::size_t i = 0, j = 0;
        int onlyOut = 0, onlyIn = 0;
        while (i < outs_.size() || j < ins_.size()) {
            if (j == ins_.size() || (i < outs_.size() && outs_[i] < ins_[j])) {
                ++onlyOut, r.borderOut = outs_[i++];
            } else if (i == outs_.size() || ins_[j] < outs_[i]) {
                ++onlyIn, r.borderIn = ins_[j++];
            } else {
                ++i, ++j;
            }
        }
        if (onlyOut == 0 && onlyIn == 0) {
            r.shape = Shape::Interior;
        } else if (onlyOut == 1 && onlyIn == 1) {
            r.shape = Shape::Border;
            // An open fan from borderOut round to borderIn: the faces must chain (a second
            // fan would leave a neighbour reached twice, caught above, or a cycle apart).
            if (!singleFan(v, r.borderOut)) return Ring{};
        } else {
            return Ring{};
        }
        return r;
    }

    // Whether walking v's faces from the border edge (v, start) visits all of them.
    bool singleFan(std::uint32_t v, std::uint32_t start) {
        std::size_t visited = 0;
        std::uint32_t at = start;
        while (visited < ringFaces_.size()) {
            bool moved = false;
            for (std::uint32_t f : ringFaces_) {
                std::uint32_t a, b;
                others(f, v, a, b);
                if (a == at) {
                    at = b;
                    moved = true;
                    break;
                }
            }
            if (!moved) break;
            ++visited;
        }
        return visited == ringFaces_.size();
    }

    std::size_t facesOnEdge(std::uint32_t a, std::uint32_t b) {
        facesOf(a, scratchFaces_);
        std::size_t n = 0;
        for (std::uint32_t f : scratchFaces_) {
            const std::uint32_t* t = &tris_[3 * f];
            if (t[0] == b || t[1] == b || t[2] == b) ++n;
        }
        return n;
    }

    void neighbours(std::uint32_t v, std::vector<std::uint32_t>& out) {
        facesOf(v, scratchFaces_);
        out.clear();
        for (std::uint32_t f : scratchFaces_)
            for (int k = 0; k < 3; ++k)
                if (tris_[3 * f + k] != v) out.push_back(tris_[3 * f + k]);
        std::sort(out.begin(), out.end());
        out.erase(std::unique(out.begin(), out.end()), out.end());
    }

    glm::dvec3 p(std::uint32_t v) const { return glm::dvec3(pos_[v]); }

    // The collapses of edge (a, b) allowed by the shapes of its ends, cheapest first, appended.
    void edgeCandidates(std::uint32_t a, const Ring& ra, std::uint32_t b, const Ring& rb,
                        std::vector<Candidate>& out) {
        if (ra.shape == Shape::Complex || rb.shape == Shape::Complex) return;
        Quadric q = quadrics_[a];
        q.add(quadrics_[b]);
        auto add = [&](std::uint32_t from, std::uint32_t to, const glm::dvec3& at,
                       const glm::vec3& fromAt) {
            const double cost = q.error(at);
            if (cost <= quadricLimit_)
                out.push_back(Candidate{cost, from, to, glm::vec3(at), fromAt});
        };
        const bool borderA = ra.shape == Shape::Border, borderB = rb.shape == Shape::Border;
        if (!borderA && !borderB) {
            const std::size_t first = out.size();
            add(a, b, p(b), pos_[a]);
            add(a, b, p(a), pos_[a]);
            const glm::dvec3 mid = (p(a) + p(b)) * 0.5;
            add(a, b, mid, pos_[a]);
            glm::dvec3 opt;
            if (q.minimum(opt) && glm::length(opt - mid) <= glm::length(p(b) - p(a)))
                add(a, b, opt, pos_[a]);
            // Only the cheapest placement: the others differ by little and cost a test each.
            if (out.size() > first + 1) {
                auto cheapest = std::min_element(
                    out.begin() + static_cast<std::ptrdiff_t>(first), out.end(),
                    [](const Candidate& x, const Candidate& y) { return x.cost < y.cost; });
                const Candidate keep = *cheapest;
                out.resize(first);
                out.push_back(keep);
            }
            return;
        }
        if (borderA != borderB) { // the interior end goes to the border end
            if (borderA)
                add(b, a, p(a), pos_[b]);
            else
                add(a, b, p(b), pos_[a]);
            return;
        }
        // Both on a border: only along a border edge, the moving end first put on the line from
        // its other border neighbour to the end it goes to.
        if (facesOnEdge(a, b) != 1) return;
        auto along = [&](std::uint32_t from, const Ring& rf, std::uint32_t to) {
            const std::uint32_t other = rf.borderOut == to ? rf.borderIn : rf.borderOut;
            if (other == kEnd || other == to) return;
            const glm::dvec3 s = p(other), e = p(to), x = p(from);
            const glm::dvec3 d = e - s;
            const double dd = glm::dot(d, d);
            const double t = dd > 0.0 ? std::clamp(glm::dot(x - s, d) / dd, 0.0, 1.0) : 0.0;
            add(from, to, e, glm::vec3(s + d * t));
        };
        along(a, ra, b);
        along(b, rb, a);
    }

    // Every vertex adjacent to both ends must be the third corner of a face on the edge.
    bool linkConditionHolds(std::uint32_t u, std::uint32_t v) {
        neighbours(u, nu_);
        neighbours(v, nv_);
        facesOf(u, scratchFaces_);
        opposite_.clear();
        for (std::uint32_t f : scratchFaces_) {
            const std::uint32_t* t = &tris_[3 * f];
            if (t[0] != v && t[1] != v && t[2] != v) continue;
            for (int k = 0; k < 3; ++k)
                if (t[k] != u && t[k] != v) opposite_.push_back(t[k]);
        }
        return hlod::linkConditionHolds(nu_, nv_, opposite_);
    }

    // Tests and, when every test passes, makes the collapse.
    bool tryCollapse(const Candidate& c) {
        if (!linkConditionHolds(c.from, c.to)) return false;
        // The faces around both ends, once each; those on the edge die.
        facesOf(c.from, fromFaces_);
        facesOf(c.to, toFaces_);
        before_.clear();
        beforeSlots_.clear();
        after_.clear();
        afterSlots_.clear();
        auto visit = [&](std::uint32_t f, bool fromSide) {
            const std::uint32_t* t = &tris_[3 * f];
            const bool hasFrom = t[0] == c.from || t[1] == c.from || t[2] == c.from;
            const bool hasTo = t[0] == c.to || t[1] == c.to || t[2] == c.to;
            if (!fromSide && hasFrom) return; // seen from c.from
            before_.push_back({t[0], t[1], t[2]});
            beforeSlots_.push_back(f);
            if (hasFrom && hasTo) return;
            std::array<std::uint32_t, 3> a{t[0], t[1], t[2]};
            for (auto& k : a)
                if (k == c.from || k == c.to) k = kNewVertex;
            after_.push_back(a);
            afterSlots_.push_back(f);
        };
        for (std::uint32_t f : fromFaces_)
            visit(f, true);
        for (std::uint32_t f : toFaces_)
            visit(f, false);
        // No face may turn by more than the limit angle, nor become degenerate.
        for (std::size_t i = 0; i < after_.size(); ++i) {
            const std::uint32_t* t = &tris_[3 * afterSlots_[i]];
            const glm::dvec3 before = glm::cross(p(t[1]) - p(t[0]), p(t[2]) - p(t[0]));
            glm::dvec3 q[3];
            for (int k = 0; k < 3; ++k)
                q[k] = after_[i][k] == kNewVertex ? glm::dvec3(c.at) : p(after_[i][k]);
            const glm::dvec3 after = glm::cross(q[1] - q[0], q[2] - q[0]);
            const double lb = glm::length(before), la = glm::length(after);
            if (!(la > 0.0)) return false;
            if (lb > 0.0 && !(glm::dot(before, after) > kMinTurnCosine * lb * la)) return false;
        }
        const CollapseRing ring{pos_, bound_,   c.from,
                                c.to, c.fromAt, glm::length(glm::dvec3(c.fromAt) - p(c.from)),
                                c.at, before_,  after_};
        const double need = collapseBound(ring, mapping_, limit_);
        if (!(need <= limit_)) return false;
        // Stored rounded up, so the float never understates it.
        float stored = static_cast<float>(need);
        if (static_cast<double>(stored) < need) stored = std::nextafter(stored, INFINITY);
        apply(c, stored);
        return true;
    }

    void apply(const Candidate& c, float newBound) {
        for (std::size_t i = 0; i < before_.size(); ++i) {
            std::uint32_t* t = &tris_[3 * beforeSlots_[i]];
            const bool hasFrom = t[0] == c.from || t[1] == c.from || t[2] == c.from;
            const bool hasTo = t[0] == c.to || t[1] == c.to || t[2] == c.to;
            if (hasFrom && hasTo) t[0] = t[1] = t[2] = kDead;
        }
        for (std::size_t i = 0; i < after_.size(); ++i) {
            std::uint32_t* t = &tris_[3 * afterSlots_[i]];
            for (int k = 0; k < 3; ++k)
                if (t[k] == c.from) t[k] = c.to;
        }
        // c.from's corners join c.to's list.
        if (head_[c.from] != kEnd) {
            if (head_[c.to] == kEnd)
                head_[c.to] = head_[c.from];
            else
                next_[tail_[c.to]] = head_[c.from];
            tail_[c.to] = tail_[c.from];
        }
        head_[c.from] = tail_[c.from] = kEnd;
        alive_[c.from] = 0;
        pos_[c.to] = c.at;
        bound_[c.to] = newBound;
        rep_[c.from] = c.to;
        quadrics_[c.to].add(quadrics_[c.from]);
        ++collapses_;
        // Re-score the kept vertex and its neighbours: only their edges to it changed cost
        // (its quadric and position), unless their best went through one of the ends.
        ++stamp_[c.to];
        rescore(c.to);
        neighbours(c.to, nu_);
        for (std::uint32_t w : nu_) {
            ++stamp_[w];
            if (best_[w].other == c.from || best_[w].other == c.to) {
                rescore(w);
                continue;
            }
            Quadric q = quadrics_[w];
            q.add(quadrics_[c.to]);
            const double cost = std::min(q.error(p(w)), q.error(p(c.to)));
            if (cost < best_[w].cost) best_[w] = Best{cost, c.to};
            if (best_[w].cost <= quadricLimit_) heap_.emplace(best_[w].cost, w, stamp_[w]);
        }
    }

    // v's cheapest edge by quadric error (any placement), queued if within the limit.
    void rescore(std::uint32_t v) {
        neighbours(v, scratchNeighbours_);
        Best b;
        for (std::uint32_t w : scratchNeighbours_) {
            Quadric q = quadrics_[v];
            q.add(quadrics_[w]);
            const glm::dvec3 mid = (p(v) + p(w)) * 0.5;
            const double cost = std::min({q.error(p(v)), q.error(p(w)), q.error(mid)});
            if (cost < b.cost || (cost == b.cost && w < b.other)) b = Best{cost, w};
        }
        best_[v] = b;
        if (b.cost <= quadricLimit_) heap_.emplace(b.cost, v, stamp_[v]);
    }

    // Tries v's collapses, cheapest first, until one is made.
    void tryVertex(std::uint32_t v) {
        const Ring rv = ringOf(v);
        if (rv.shape == Shape::Complex) return;
        neighbours(v, candidatesOf_);
        candidates_.clear();
        for (std::uint32_t w : candidatesOf_) {
            const Ring rw = ringOf(w);
            edgeCandidates(v, rv, w, rw, candidates_);
        }
        std::sort(candidates_.begin(), candidates_.end(),
                  [](const Candidate& x, const Candidate& y) {
                      return std::tie(x.cost, x.from, x.to) < std::tie(y.cost, y.from, y.to);
                  });
        for (const Candidate& c : candidates_)
            if (tryCollapse(c)) return;
    }

    std::vector<glm::vec3> pos_;
    std::vector<std::uint32_t> tris_;
    std::vector<float> bound_; // per vertex (MappingBound.h)
    std::vector<Quadric> quadrics_;
    std::vector<std::uint32_t> rep_;
    std::vector<std::uint8_t> alive_;
    std::vector<std::uint32_t> head_, tail_, next_, stamp_;
    std::vector<Best> best_;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> heap_;
    float limit_;
    double quadricLimit_;
    std::size_t collapses_ = 0;
    // Scratch.
    std::vector<std::uint32_t> ringFaces_, outs_, ins_, scratchFaces_, nu_, nv_, opposite_;
    std::vector<std::uint32_t> fromFaces_, toFaces_, beforeSlots_, afterSlots_;
    std::vector<std::uint32_t> scratchNeighbours_, candidatesOf_;
    std::vector<Candidate> candidates_;
    std::vector<std::array<std::uint32_t, 3>> before_, after_;
    MappingScratch mapping_;
};

} // namespace

CertifiedSimplifyResult simplifyCertified(std::span<const glm::vec3> positions,
                                          std::span<const std::uint32_t> indices,
                                          std::span<const float> vertexBounds, double limit) {
    if (indices.empty() || !(limit > 0.0)) {
        CertifiedSimplifyResult out;
        out.positions.assign(positions.begin(), positions.end());
        out.indices.assign(indices.begin(), indices.end());
        out.vertexBounds.assign(positions.size(), 0.0f);
        if (vertexBounds.size() == positions.size())
            out.vertexBounds.assign(vertexBounds.begin(), vertexBounds.end());
        out.representative.resize(positions.size());
        for (std::uint32_t v = 0; v < positions.size(); ++v)
            out.representative[v] = v;
        return out;
    }
    Simplifier s(positions, indices, vertexBounds, limit);
    s.run();
    return s.result();
}

} // namespace hlod
