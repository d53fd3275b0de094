// Vertex and index streams as the Khronos extensions KHR_mesh_quantization and
// EXT_meshopt_compression store them, made with meshoptimizer 0.18's encoders and filters
// (A. Kapoulkine, meshoptimizer: "Vertex/index buffer compression" and "Vertex filters"; the
// extension specification fixes the bitstreams: index codec version 1, vertex codec version 0).
//
// Positions: unsigned 16-bit integers on a uniform grid (KHR_mesh_quantization, not
// normalised; the node transform carries offset and step). The grid step is a power of two, the
// requested step rounded down (never coarser than asked) but at least what 16 bits need to span
// the mesh's extent; so a decoded position is off by at most step / 2 on each axis. The grid's
// origin (the node translation) is, per axis, the smallest coordinate rounded down to a multiple
// of a power of ten at most a tenth of what the 16 bits leave beyond the extent (so it still
// spans the largest): "-34" rather than "-33.83799743652344" in the JSON, the same step and so
// the same error bound.
// Normals: octahedral, 8-bit (filter OCTAHEDRAL, about 1 degree). Texture coordinates: floats
// with a 8-bit exponent per coordinate and a 16-bit mantissa (filter EXPONENTIAL, relative
// error 2^-17). Colours: 8-bit normalised, as they are.
//
// Units: positions in metres of the mesh's frame. Failure: none for valid input (the streams
// are sized here); the caller guarantees indices < vertex count.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace hlod {

// Where stored positions sit in the mesh's frame: position = offset + step * stored.
struct PositionGrid {
    glm::dvec3 offset{0.0};
    double step = 1.0; // a power of two
};

struct QuantizedPositions {
    std::vector<std::uint16_t> values; // x, y, z, 0 per vertex (byte stride 8)
    glm::dvec3 offset{0.0};            // position = offset + step * value
    double step = 1.0;                 // grid spacing, a power of two
    glm::u16vec3 min{0}, max{0};       // accessor bounds of the values
};

// The grid step for positions spanning `extent` (largest axis, metres) at `requested` precision
// (> 0; 0 = the finest grid 16 bits allow). See the header comment.
double positionGridStep(double extent, double requested);

// The grid for positions within [lo, hi] (lo <= hi) at `requested` precision (see above).
PositionGrid positionGrid(const glm::dvec3& lo, const glm::dvec3& hi, double requested);

// Positions on `grid`, which must span them (every value within 0 .. 65535).
QuantizedPositions quantizePositions(std::span<const glm::vec3> positions,
                                     const PositionGrid& grid);

// Positions on the grid of their own bounds.
QuantizedPositions quantizePositions(std::span<const glm::vec3> positions, double requestedStep);

// 4 bytes per vector: octahedral x, y, z = 1, w = 0 (meshopt_encodeFilterOct, 8 bits).
std::vector<std::int8_t> octahedralNormals(std::span<const glm::vec3> normals);

// 2 words per uv (meshopt_encodeFilterExp, 16-bit mantissa, an exponent each).
std::vector<std::uint32_t> exponentialUvs(std::span<const glm::vec2> uvs);

// What a decoder makes of a stream stored with `filter` (nullptr or "NONE", "OCTAHEDRAL",
// "EXPONENTIAL"): meshopt_decodeFilter* applied to a copy of `count` elements of `stride` bytes.
// The vertex codec itself is lossless, so this is the stream's content once decoded.
std::vector<std::uint8_t> decodedAttributes(const void* data, std::size_t count, std::size_t stride,
                                            const char* filter);

// meshopt_encodeVertexBuffer of `count` elements of `stride` bytes (a multiple of 4, <= 256).
std::vector<std::uint8_t> compressAttributes(const void* data, std::size_t count,
                                             std::size_t stride);

// meshopt_encodeIndexBuffer (codec version 1) of a triangle list.
std::vector<std::uint8_t> compressTriangles(std::span<const std::uint32_t> indices,
                                            std::size_t vertexCount);

} // namespace hlod
