// Stream encoders for KHR_mesh_quantization + EXT_meshopt_compression (see GlbMeshopt.h).
#include "pipeline/io/GlbMeshopt.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <mutex>

#include <meshoptimizer.h>

namespace hlod {

namespace {

constexpr double kMaxSteps = 65535.0; // 16 bits

// 2^k with 2^k <= x (x > 0, finite).
double pow2Floor(double x) {
    int e = 0;
    std::frexp(x, &e); // x = m * 2^e, m in [0.5, 1)
    return std::ldexp(1.0, e - 1);
}

double pow2Ceil(double x) {
    const double f = pow2Floor(x);
    return f == x ? f : 2.0 * f;
}

} // namespace

double positionGridStep(double extent, double requested) {
    const double finest =
        extent > 0.0 && std::isfinite(extent) ? pow2Ceil(extent / kMaxSteps) : 0.0;
    const double asked = requested > 0.0 && std::isfinite(requested) ? pow2Floor(requested) : 0.0;
    const double step = std::max(finest, asked);
    return step > 0.0 ? step : 1.0; // a single point: any grid holds it
}

namespace {

// A short decimal d <= lo with hi - d <= kMaxSteps * step (lo itself when none is found): lo
// rounded down to a multiple of a power of ten at most a tenth of the slack the 16 bits leave.
double shortOrigin(double lo, double hi, double step) {
    const double slack = kMaxSteps * step - (hi - lo);
    if (!(slack > 0.0) || !std::isfinite(lo) || !std::isfinite(slack)) return lo;
    const int k = static_cast<int>(std::floor(std::log10(slack))) - 1;
    if (k < -22 || k > 22) return lo; // powers of ten beyond 1e22 are not exact doubles
    const double ten = std::pow(10.0, std::abs(k)); // exact: 10^|k| <= 1e22
    const double scaled = k >= 0 ? lo / ten : lo * ten;
    if (!(std::abs(scaled) < 4.5e15)) return lo; // floor must stay exact
    double n = std::floor(scaled);
    double d = k >= 0 ? n * ten : n / ten; // the double nearest the decimal n * 10^k
    if (d > lo) d = k >= 0 ? (n - 1.0) * ten : (n - 1.0) / ten;
    return d <= lo && hi - d <= kMaxSteps * step ? d : lo;
}

} // namespace

PositionGrid positionGrid(const glm::dvec3& lo, const glm::dvec3& hi, double requested) {
    const glm::dvec3 ext = hi - lo;
    PositionGrid g;
    g.step = positionGridStep(std::max({ext.x, ext.y, ext.z}), requested);
    for (int a = 0; a < 3; ++a)
        g.offset[a] = shortOrigin(lo[a], hi[a], g.step);
    return g;
}

QuantizedPositions quantizePositions(std::span<const glm::vec3> positions,
                                     const PositionGrid& grid) {
    QuantizedPositions q;
    q.offset = grid.offset;
    q.step = grid.step;
    if (positions.empty()) return q;
    q.values.resize(positions.size() * 4, 0);
    q.min = glm::u16vec3(65535);
    for (std::size_t i = 0; i < positions.size(); ++i) {
        for (int a = 0; a < 3; ++a) {
            const double v = std::round((double(positions[i][a]) - grid.offset[a]) / grid.step);
            const auto u = static_cast<std::uint16_t>(std::clamp(v, 0.0, kMaxSteps));
            q.values[i * 4 + a] = u;
            q.min[a] = std::min(q.min[a], u);
            q.max[a] = std::max(q.max[a], u);
        }
    }
    return q;
}

QuantizedPositions quantizePositions(std::span<const glm::vec3> positions, double requestedStep) {
    if (positions.empty()) return {};
    glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    for (const glm::vec3& p : positions) {
        lo = glm::min(lo, glm::dvec3(p));
        hi = glm::max(hi, glm::dvec3(p));
    }
    return quantizePositions(positions, positionGrid(lo, hi, requestedStep));
}

std::vector<std::int8_t> octahedralNormals(std::span<const glm::vec3> normals) {
    std::vector<float> in(normals.size() * 4, 0.0f);
    for (std::size_t i = 0; i < normals.size(); ++i) {
        glm::vec3 n = normals[i];
        const float len = glm::length(n);
        n = len > 0.0f && std::isfinite(len) ? n / len : glm::vec3(0.0f, 1.0f, 0.0f);
        in[i * 4 + 0] = n.x;
        in[i * 4 + 1] = n.y;
        in[i * 4 + 2] = n.z;
    }
    std::vector<std::int8_t> out(normals.size() * 4, 0);
    if (!normals.empty()) meshopt_encodeFilterOct(out.data(), normals.size(), 4, 8, in.data());
    return out;
}

std::vector<std::uint32_t> exponentialUvs(std::span<const glm::vec2> uvs) {
    std::vector<float> in(uvs.size() * 2);
    for (std::size_t i = 0; i < uvs.size(); ++i) {
        // Non-finite coordinates would give garbage exponents: sample the texture's corner.
        in[i * 2 + 0] = std::isfinite(uvs[i].x) ? uvs[i].x : 0.0f;
        in[i * 2 + 1] = std::isfinite(uvs[i].y) ? uvs[i].y : 0.0f;
    }
    std::vector<std::uint32_t> out(uvs.size() * 2, 0);
    // One exponent per coordinate (each word its own "vector"): a u of many periods does not
    // coarsen v, which stacked atlases need to within a texel (StackedAtlas.h).
    if (!uvs.empty()) meshopt_encodeFilterExp(out.data(), uvs.size() * 2, 4, 16, in.data());
    return out;
}

std::vector<std::uint8_t> decodedAttributes(const void* data, std::size_t count, std::size_t stride,
                                            const char* filter) {
    const auto* p = static_cast<const std::uint8_t*>(data);
    std::vector<std::uint8_t> out(p, p + count * stride);
    if (count == 0 || filter == nullptr) return out;
    if (std::strcmp(filter, "OCTAHEDRAL") == 0) meshopt_decodeFilterOct(out.data(), count, stride);
    if (std::strcmp(filter, "EXPONENTIAL") == 0) meshopt_decodeFilterExp(out.data(), count, stride);
    return out;
}

std::vector<std::uint8_t> compressAttributes(const void* data, std::size_t count,
                                             std::size_t stride) {
    std::vector<std::uint8_t> out(meshopt_encodeVertexBufferBound(count, stride));
    out.resize(meshopt_encodeVertexBuffer(out.data(), out.size(), data, count, stride));
    return out;
}

std::vector<std::uint8_t> compressTriangles(std::span<const std::uint32_t> indices,
                                            std::size_t vertexCount) {
    // The extension's TRIANGLES mode is index codec version 1 (decodable by meshoptimizer
    // 0.14+ and every runtime decoder). A process-wide setting: made once.
    static std::once_flag once;
    std::call_once(once, [] { meshopt_encodeIndexVersion(1); });
    std::vector<std::uint8_t> out(meshopt_encodeIndexBufferBound(indices.size(), vertexCount));
    out.resize(meshopt_encodeIndexBuffer(out.data(), out.size(), indices.data(), indices.size()));
    return out;
}

} // namespace hlod
