// Tagged binary layout of a ClusterTree: magic, version, volume, k, root, then per node its
// fixed fields and its children (64-bit count + ids). See ClusterTreeBinary.h.
#include "pipeline/cluster/ClusterTreeBinary.h"

#include <cstdint>
#include <cstring>
#include <type_traits>

#include "pipeline/core/Error.h"

namespace hlod {

namespace {

constexpr std::uint32_t kMagic = 0x54444c48; // "HLDT"
constexpr std::uint32_t kVersion = 1;

template <typename T> void put(std::string& out, const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    out.append(reinterpret_cast<const char*>(&v), sizeof v);
}

class Reader {
public:
    Reader(const std::string& b, const std::filesystem::path& o) : bytes_(b), origin_(o) {}
    template <typename T> T get() {
        static_assert(std::is_trivially_copyable_v<T>);
        T v;
        if (bytes_.size() - pos_ < sizeof v) fail("truncated");
        std::memcpy(&v, bytes_.data() + pos_, sizeof v);
        pos_ += sizeof v;
        return v;
    }
    std::uint64_t count(std::size_t elementSize) {
        const auto n = get<std::uint64_t>();
        if (n > (bytes_.size() - pos_) / elementSize) fail("truncated");
        return n;
    }
    bool atEnd() const { return pos_ == bytes_.size(); }
    [[noreturn]] void fail(const std::string& why) const {
        throw Error(ErrorCode::Malformed, origin_, "cluster tree data is " + why);
    }

private:
    const std::string& bytes_;
    const std::filesystem::path& origin_;
    std::size_t pos_ = 0;
};

} // namespace

std::string writeClusterTreeBinary(const ClusterTree& tree) {
    std::string out;
    put(out, kMagic);
    put(out, kVersion);
    put(out, static_cast<std::uint32_t>(tree.volume));
    put(out, tree.k);
    put(out, tree.root);
    put(out, static_cast<std::uint64_t>(tree.nodes.size()));
    for (const ClusterNode& n : tree.nodes) {
        put(out, n.parent);
        put(out, n.instance);
        put(out, n.box);
        put(out, n.sphere);
        put(out, n.fill);
        put(out, n.cost);
        put(out, static_cast<std::int32_t>(n.level));
        put(out, static_cast<std::uint8_t>(n.locked ? 1 : 0));
        put(out, static_cast<std::uint64_t>(n.children.size()));
        out.append(reinterpret_cast<const char*>(n.children.data()),
                   n.children.size() * sizeof(Id));
    }
    return out;
}

ClusterTree readClusterTreeBinary(const std::string& bytes, const std::filesystem::path& origin) {
    Reader r(bytes, origin);
    if (r.get<std::uint32_t>() != kMagic) r.fail("not a cluster tree (bad magic)");
    if (r.get<std::uint32_t>() != kVersion) r.fail("of an unknown version");
    ClusterTree tree;
    const auto volume = r.get<std::uint32_t>();
    if (volume > static_cast<std::uint32_t>(VolumeType::Original)) r.fail("of an unknown volume");
    tree.volume = static_cast<VolumeType>(volume);
    tree.k = r.get<double>();
    tree.root = r.get<Id>();
    // A node takes at least its fixed fields: cap the count by the buffer before allocating.
    constexpr std::size_t kFixed =
        2 * sizeof(Id) + sizeof(Aabb) + sizeof(Sphere) + 2 * 8 + 4 + 1 + 8;
    tree.nodes.resize(r.count(kFixed));
    for (ClusterNode& n : tree.nodes) {
        n.parent = r.get<Id>();
        n.instance = r.get<Id>();
        n.box = r.get<Aabb>();
        n.sphere = r.get<Sphere>();
        n.fill = r.get<double>();
        n.cost = r.get<double>();
        n.level = r.get<std::int32_t>();
        n.locked = r.get<std::uint8_t>() != 0;
        n.children.resize(r.count(sizeof(Id)));
        for (Id& c : n.children)
            c = r.get<Id>();
    }
    if (!r.atEnd()) r.fail("followed by trailing bytes");
    const std::size_t size = tree.nodes.size();
    if (size == 0 ? tree.root != kNoId
                  : (tree.root >= size || tree.nodes[tree.root].parent != kNoId))
        r.fail("inconsistent (bad root)");
    for (Id i = 0; i < size; ++i) {
        for (Id c : tree.nodes[i].children) {
            if (c >= size || c == tree.root || tree.nodes[c].parent != i)
                r.fail("inconsistent (node " + std::to_string(i) + " has a bad child)");
        }
    }
    return tree;
}

} // namespace hlod
