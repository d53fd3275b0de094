// Exterior flood fill on a sparse OpenVDB distance grid, at voxel resolution but visiting
// empty space in 8^3 blocks: the building block of hidden-interior removal in RemeshProxy.
//
// A voxel is solid when it is active and its unsigned distance is below `solidBelow`. The
// exterior is every non-solid voxel 6-connected to the space outside the grid's bounding box.
// Empty blocks (no leaf node, or a leaf without solid voxels) are filled as a whole; blocks
// with solid voxels are filled bit-parallel in 512-bit masks (one 64-bit word per x slice,
// matching OpenVDB's leaf voxel order x-major, z fastest). This is the classic two-level
// seed fill used by sparse volume tools: cost grows with the number of blocks, not voxels.
//
// Contract: a closed surface of solid voxels (a shell at least one voxel thick, which a
// distance threshold above half a voxel guarantees for any surface, see RemeshProxy.cpp)
// separates what it encloses from the exterior, so enclosed voxels report !isExterior.
// Deterministic (a pure function of the grid's topology and values).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <openvdb/openvdb.h>

namespace hlod {

class ExteriorFill {
public:
    ExteriorFill(const openvdb::FloatGrid& distance, float solidBelow);

    bool isExterior(const openvdb::Coord& voxel) const;
    // The exterior voxels of the 8^3 block holding `voxel`, bit n = OpenVDB leaf offset n.
    std::array<std::uint64_t, 8> exteriorMask(const openvdb::Coord& voxel) const;
    bool isSolid(const openvdb::Coord& voxel) const;
    // Origins (multiples of 8) of blocks without solid voxels that the fill did not reach and
    // that touch a block with solid voxels: enclosed empty space next to a surface.
    std::vector<openvdb::Coord> enclosedEmptyBlocksNearSurface() const;

    std::size_t blockCount() const { return state_.size(); }
    std::size_t solidBlockCount() const { return masks_.size(); }

private:
    using Mask = std::array<std::uint64_t, 8>;
    struct BlockMasks {
        Mask solid{};
        Mask exterior{};
    };
    std::int64_t blockIndex(const openvdb::Coord& blockCoord) const;
    void fill();
    void processBlock(std::int64_t block, std::vector<std::int64_t>& queue);
    void seedNeighbor(std::int64_t neighbor, int axis, bool positive, const Mask& exterior,
                      std::vector<std::int64_t>& queue);

    openvdb::Coord min_; // block coordinates of the padded box
    openvdb::Coord dims_;
    std::vector<std::int32_t> state_; // >= 0: index into masks_; -1 empty; -2 empty and reached
    std::vector<BlockMasks> masks_;
    std::vector<std::uint8_t> queued_;
};

} // namespace hlod
