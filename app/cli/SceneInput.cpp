#include "SceneInput.h"

#include "ProgressBar.h"
#include "pipeline/io/SampleScene.h"

namespace hlod::cli {

ImportOptions importOptionsFromArgs(const Args& args) {
    ParamValues values = defaultValues(NodeKind::Import);
    for (const auto& [decl, value] : paramsFromArgs(args, {NodeKind::Import}))
        values[decl->key] = value;
    return importOptionsFrom(values);
}

LoadedScene loadSceneArgs(const std::vector<std::string>& positionals,
                          const ImportOptions& options) {
    LoadedScene out;
    if (positionals.empty()) {
        out.scene = makeSampleScene();
        out.inputs = {"sample:plant"};
        return out;
    }
    if (positionals.size() == 1 && isPackageFolder(positionals[0])) {
        out.package = readPackage(positionals[0]);
        out.scene = readPackageScene(*out.package);
        out.inputs = positionals;
        for (const auto& e : std::filesystem::recursive_directory_iterator(positionals[0])) {
            if (e.is_regular_file()) out.fileBytes += e.file_size();
        }
        return out;
    }
    std::vector<std::filesystem::path> paths(positionals.begin(), positionals.end());
    ProgressBar bar;
    out.scene = importScene(paths, options, bar.progress());
    bar.finish();
    out.inputs = positionals;
    for (const auto& f : out.scene.sourceFiles) {
        std::error_code ec;
        const auto size = std::filesystem::file_size(f, ec);
        if (!ec) out.fileBytes += size;
    }
    return out;
}

} // namespace hlod::cli
