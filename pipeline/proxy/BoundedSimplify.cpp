// Quadric simplification, certified both ways, repaired by restoring the input triangles where
// the check failed, see BoundedSimplify.h.
#include "pipeline/proxy/BoundedSimplify.h"

#include "pipeline/proxy/DeviationCheck.h"
#include "pipeline/proxy/QuadricSimplify.h"

namespace hlod {

namespace {

constexpr std::uint32_t kNone = 0xffffffffu;

// Appends the input triangles `failing` to the result, as they are in the input. A corner
// whose vertex kept its input position is shared with the simplified triangles; one the
// simplifier moved gets one copy (shared by every patch that uses it).
void patch(std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices,
           std::span<const std::uint32_t> failing, BoundedSimplifyResult& out) {
    std::vector<std::uint32_t> copyOf(positions.size(), kNone);
    for (std::uint32_t t : failing) {
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t v = indices[3 * t + k];
            if (out.positions[v] == positions[v]) {
                out.indices.push_back(v);
                continue;
            }
            if (copyOf[v] == kNone) {
                copyOf[v] = static_cast<std::uint32_t>(out.positions.size());
                out.positions.push_back(positions[v]);
                out.copies.push_back(v);
            }
            out.indices.push_back(copyOf[v]);
        }
    }
}

} // namespace

namespace {

// The final check and repair of a bounded simplification `r` of the input (BoundedSimplify.h).
BoundedSimplifyResult checkAndPatch(std::span<const glm::vec3> positions,
                                    std::span<const std::uint32_t> indices, double maxError,
                                    QuadricSimplifyResult r, BoundedSimplifyStats& st) {
    BoundedSimplifyResult input{
        {indices.begin(), indices.end()}, {positions.begin(), positions.end()}, {}};
    if (r.indices.size() == indices.size()) { // nothing collapsed: unchanged
        st.unchanged = true;
        return input;
    }
    // Every reshaped face was certified when it was made (QuadricSimplify.h): the samples'
    // direction is what is left to prove. Every failing input triangle is reported.
    DeviationChecker checker(positions, indices, maxError);
    DeviationViolations violations;
    BoundedSimplifyResult out{std::move(r.indices), std::move(r.positions), {}};
    if (checker.findViolations(out.positions, out.indices, violations, indices.size() / 3, false))
        return out;
    st.patched = violations.originalTriangles.size();
    if (3 * st.patched + out.indices.size() >= indices.size()) { // no smaller: keep the input
        st.unchanged = true;
        return input;
    }
    patch(positions, indices, violations.originalTriangles, out);
    return out;
}

// The input unchanged when there is nothing to do, else `simplify`'s result checked and patched.
template <typename Simplify>
BoundedSimplifyResult run(std::span<const glm::vec3> positions,
                          std::span<const std::uint32_t> indices, double maxError,
                          BoundedSimplifyStats* stats, Simplify&& simplify) {
    BoundedSimplifyStats local;
    BoundedSimplifyStats& st = stats ? *stats : local;
    st = BoundedSimplifyStats{};
    if (indices.empty() || !(maxError > 0.0)) {
        st.unchanged = true;
        return BoundedSimplifyResult{
            {indices.begin(), indices.end()}, {positions.begin(), positions.end()}, {}};
    }
    return checkAndPatch(positions, indices, maxError, simplify(), st);
}

} // namespace

BoundedSimplifyResult simplifyWithinDeviation(std::span<const glm::vec3> positions,
                                              std::span<const std::uint32_t> indices,
                                              double maxError,
                                              const BoundedSimplifyOptions& options,
                                              BoundedSimplifyStats* stats) {
    return run(positions, indices, maxError, stats, [&] {
        return simplifyWithQuadrics(positions, indices, {}, options.targetFraction * maxError,
                                    maxError);
    });
}

BoundedSimplifyResult simplifyWithinDeviationFrom(std::span<const glm::vec3> positions,
                                                  std::span<const std::uint32_t> indices,
                                                  const QuadricStart& start, double maxError,
                                                  const BoundedSimplifyOptions& options,
                                                  BoundedSimplifyStats* stats) {
    return run(positions, indices, maxError, stats, [&] {
        return simplifyWithQuadricsFrom(positions, indices, start,
                                        options.targetFraction * maxError, maxError);
    });
}

} // namespace hlod
