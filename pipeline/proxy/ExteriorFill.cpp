// Two-level (block / voxel) exterior seed fill over an OpenVDB tree, see ExteriorFill.h.
#include "pipeline/proxy/ExteriorFill.h"

namespace hlod {

namespace {

constexpr std::int32_t kEmpty = -1;
constexpr std::int32_t kEmptyReached = -2;
// Bit b of word x is voxel (x, b / 8, b % 8) of a block: OpenVDB's leaf offset x*64 + y*8 + z.
constexpr std::uint64_t kZ0 = 0x0101010101010101ull;
constexpr std::uint64_t kZ7 = kZ0 << 7;
constexpr std::uint64_t kY0 = 0xffull;
constexpr std::uint64_t kY7 = kY0 << 56;
constexpr std::uint64_t kAll = ~0ull;

openvdb::Coord blockOf(const openvdb::Coord& voxel) {
    return openvdb::Coord(voxel.x() >> 3, voxel.y() >> 3, voxel.z() >> 3);
}

} // namespace

ExteriorFill::ExteriorFill(const openvdb::FloatGrid& distance, float solidBelow) {
    openvdb::Coord lo(std::numeric_limits<openvdb::Int32>::max());
    openvdb::Coord hi(std::numeric_limits<openvdb::Int32>::min());
    std::vector<std::pair<openvdb::Coord, Mask>> solidLeaves;
    for (auto leaf = distance.tree().cbeginLeaf(); leaf; ++leaf) {
        Mask solid{};
        bool any = false;
        for (auto v = leaf->cbeginValueOn(); v; ++v) {
            if (*v < solidBelow) {
                const openvdb::Index n = v.pos();
                solid[n >> 6] |= 1ull << (n & 63);
                any = true;
            }
        }
        if (!any) continue;
        const openvdb::Coord b = blockOf(leaf->origin());
        lo.minComponent(b);
        hi.maxComponent(b);
        solidLeaves.emplace_back(b, solid);
    }
    if (solidLeaves.empty()) {
        lo = hi = openvdb::Coord(0);
    }
    // One block of padding on every side so the outside is connected around everything.
    min_ = lo - openvdb::Coord(1);
    dims_ = hi - lo + openvdb::Coord(3);
    const std::size_t count = static_cast<std::size_t>(dims_.x()) * dims_.y() * dims_.z();
    state_.assign(count, kEmpty);
    queued_.assign(count, 0);
    masks_.reserve(solidLeaves.size());
    for (const auto& [b, solid] : solidLeaves) {
        state_[static_cast<std::size_t>(blockIndex(b))] = static_cast<std::int32_t>(masks_.size());
        masks_.push_back(BlockMasks{solid, Mask{}});
    }
    fill();
}

std::int64_t ExteriorFill::blockIndex(const openvdb::Coord& b) const {
    const openvdb::Coord r = b - min_;
    if (r.x() < 0 || r.y() < 0 || r.z() < 0 || r.x() >= dims_.x() || r.y() >= dims_.y() ||
        r.z() >= dims_.z()) {
        return -1;
    }
    return (static_cast<std::int64_t>(r.x()) * dims_.y() + r.y()) * dims_.z() + r.z();
}

void ExteriorFill::fill() {
    // The padded corner block is empty and outside everything.
    std::vector<std::int64_t> queue{0};
    state_[0] = kEmptyReached;
    queued_[0] = 1;
    while (!queue.empty()) {
        const std::int64_t block = queue.back();
        queue.pop_back();
        queued_[static_cast<std::size_t>(block)] = 0;
        processBlock(block, queue);
    }
}

void ExteriorFill::processBlock(std::int64_t block, std::vector<std::int64_t>& queue) {
    const std::int32_t state = state_[static_cast<std::size_t>(block)];
    Mask exterior;
    if (state == kEmptyReached) {
        exterior.fill(kAll);
    } else {
        // Grow the seeded voxels inside the block until they stop at solid voxels.
        BlockMasks& m = masks_[static_cast<std::size_t>(state)];
        Mask e = m.exterior;
        for (;;) {
            Mask g;
            for (int x = 0; x < 8; ++x) {
                const std::uint64_t w = e[x];
                std::uint64_t v = w | ((w & ~kZ7) << 1) | ((w & ~kZ0) >> 1) | (w << 8) | (w >> 8);
                if (x > 0) v |= e[x - 1];
                if (x < 7) v |= e[x + 1];
                g[x] = v & ~m.solid[x];
            }
            if (g == e) break;
            e = g;
        }
        m.exterior = e;
        exterior = e;
    }
    const openvdb::Coord b(static_cast<openvdb::Int32>(block / (dims_.y() * dims_.z())),
                           static_cast<openvdb::Int32>((block / dims_.z()) % dims_.y()),
                           static_cast<openvdb::Int32>(block % dims_.z()));
    for (int axis = 0; axis < 3; ++axis) {
        for (int side = 0; side < 2; ++side) {
            openvdb::Coord n = b + min_;
            n[axis] += side ? 1 : -1;
            const std::int64_t neighbor = blockIndex(n);
            if (neighbor >= 0) seedNeighbor(neighbor, axis, side == 1, exterior, queue);
        }
    }
}

void ExteriorFill::seedNeighbor(std::int64_t neighbor, int axis, bool positive,
                                const Mask& exterior, std::vector<std::int64_t>& queue) {
    // The exterior voxels on our face, moved onto the neighbour's touching face.
    Mask seed{};
    bool any = false;
    for (int x = 0; x < 8; ++x) {
        std::uint64_t s = 0;
        if (axis == 0) {
            if (x == (positive ? 0 : 7)) s = exterior[positive ? 7 : 0];
        } else if (axis == 1) {
            s = positive ? (exterior[x] & kY7) >> 56 : (exterior[x] & kY0) << 56;
        } else {
            s = positive ? (exterior[x] & kZ7) >> 7 : (exterior[x] & kZ0) << 7;
        }
        seed[x] = s;
        any |= s != 0;
    }
    if (!any) return;
    const auto idx = static_cast<std::size_t>(neighbor);
    std::int32_t& state = state_[idx];
    bool changed = false;
    if (state == kEmpty) {
        state = kEmptyReached;
        changed = true;
    } else if (state >= 0) {
        BlockMasks& m = masks_[static_cast<std::size_t>(state)];
        for (int x = 0; x < 8; ++x) {
            const std::uint64_t fresh = seed[x] & ~m.solid[x] & ~m.exterior[x];
            if (fresh) {
                m.exterior[x] |= fresh;
                changed = true;
            }
        }
    }
    if (changed && !queued_[idx]) {
        queued_[idx] = 1;
        queue.push_back(neighbor);
    }
}

bool ExteriorFill::isExterior(const openvdb::Coord& voxel) const {
    const std::int64_t block = blockIndex(blockOf(voxel));
    if (block < 0) return true;
    const std::int32_t state = state_[static_cast<std::size_t>(block)];
    if (state == kEmptyReached) return true;
    if (state == kEmpty) return false;
    const openvdb::Index n = openvdb::FloatTree::LeafNodeType::coordToOffset(voxel);
    return (masks_[static_cast<std::size_t>(state)].exterior[n >> 6] >> (n & 63)) & 1ull;
}

std::array<std::uint64_t, 8> ExteriorFill::exteriorMask(const openvdb::Coord& voxel) const {
    std::array<std::uint64_t, 8> out{};
    const std::int64_t block = blockIndex(blockOf(voxel));
    const std::int32_t state = block < 0 ? kEmptyReached : state_[static_cast<std::size_t>(block)];
    if (state == kEmptyReached)
        out.fill(kAll);
    else if (state >= 0)
        out = masks_[static_cast<std::size_t>(state)].exterior;
    return out;
}

bool ExteriorFill::isSolid(const openvdb::Coord& voxel) const {
    const std::int64_t block = blockIndex(blockOf(voxel));
    if (block < 0) return false;
    const std::int32_t state = state_[static_cast<std::size_t>(block)];
    if (state < 0) return false;
    const openvdb::Index n = openvdb::FloatTree::LeafNodeType::coordToOffset(voxel);
    return (masks_[static_cast<std::size_t>(state)].solid[n >> 6] >> (n & 63)) & 1ull;
}

std::vector<openvdb::Coord> ExteriorFill::enclosedEmptyBlocksNearSurface() const {
    std::vector<openvdb::Coord> out;
    for (openvdb::Int32 x = 0; x < dims_.x(); ++x) {
        for (openvdb::Int32 y = 0; y < dims_.y(); ++y) {
            for (openvdb::Int32 z = 0; z < dims_.z(); ++z) {
                const openvdb::Coord b = openvdb::Coord(x, y, z) + min_;
                if (state_[static_cast<std::size_t>(blockIndex(b))] != kEmpty) continue;
                bool nearSolid = false;
                for (int dx = -1; dx <= 1 && !nearSolid; ++dx) {
                    for (int dy = -1; dy <= 1 && !nearSolid; ++dy) {
                        for (int dz = -1; dz <= 1 && !nearSolid; ++dz) {
                            const std::int64_t n = blockIndex(b + openvdb::Coord(dx, dy, dz));
                            nearSolid = n >= 0 && state_[static_cast<std::size_t>(n)] >= 0;
                        }
                    }
                }
                if (nearSolid) out.push_back(openvdb::Coord(b.x() * 8, b.y() * 8, b.z() * 8));
            }
        }
    }
    return out;
}

} // namespace hlod
