// dlopen-based module loading, see OnDemand.h.
#include "pipeline/core/OnDemand.h"

#include <cstdlib>
#include <dlfcn.h>
#include <filesystem>
#include <map>
#include <mutex>
#include <pthread.h>
#include <vector>

#include "pipeline/core/Error.h"

namespace hlod {

namespace fs = std::filesystem;

namespace {

std::vector<fs::path> moduleFolders() {
    if (const char* dir = std::getenv("HLOD_MODULE_DIR"); dir && *dir) return {fs::path(dir)};
    std::vector<fs::path> out = programFolders();
#ifdef HLOD_BUILD_MODULE_DIR
    out.emplace_back(HLOD_BUILD_MODULE_DIR);
#endif
    return out;
}

std::mutex loadMutex;

// The importers load their module in a forked child (IsolatedImport.h): a fork while another
// thread is loading a module would leave the child with the lock held. fork() waits for it.
[[maybe_unused]] const int kForkSafe = [] {
    return ::pthread_atfork([] { loadMutex.lock(); }, [] { loadMutex.unlock(); },
                            [] { loadMutex.unlock(); });
}();

} // namespace

std::vector<fs::path> programFolders() {
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    if (ec) return {};
    return {self.parent_path(), self.parent_path().parent_path() / "lib" / "hlod-studio"};
}

const void* onDemandModule(const std::string& name, const std::string& purpose) {
    static std::map<std::string, const void*> loaded;
    const std::lock_guard lock(loadMutex);
    if (auto it = loaded.find(name); it != loaded.end()) return it->second;
    const std::string file = "libhlod-" + name + ".so";
    std::string tried;
    for (const fs::path& folder : moduleFolders()) {
        const fs::path path = folder / file;
        std::error_code ec;
        if (!fs::is_regular_file(path, ec)) {
            tried += (tried.empty() ? "" : ", ") + folder.string();
            continue;
        }
        void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!handle) {
            const char* why = ::dlerror();
            throw Error(ErrorCode::FileUnreadable, path,
                        "cannot load the " + purpose + " module: " + (why ? why : "dlopen failed"));
        }
        const std::string entry = "hlod_module_" + name;
        using Entry = const void* (*)();
        auto fn = reinterpret_cast<Entry>(::dlsym(handle, entry.c_str()));
        if (!fn)
            throw Error(ErrorCode::Malformed, path,
                        "is not an HLOD Studio module (no " + entry + ")");
        const void* table = fn();
        loaded.emplace(name, table);
        return table;
    }
    throw Error(ErrorCode::FileNotFound, "the " + purpose + " module " + file +
                                             " is not installed (looked in " + tried +
                                             "; HLOD_MODULE_DIR names the folder to use instead)");
}

} // namespace hlod
