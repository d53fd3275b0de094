#include "SceneInput.h"

#include "ProgressBar.h"
#include "pipeline/io/SampleScene.h"

namespace hlod::cli {

LoadedScene loadSceneArgs(const std::vector<std::string>& positionals,
                          const ImportOptions& options) {
    LoadedScene out;
    if (positionals.empty()) {
        out.scene = makeSampleScene();
        out.inputs = {"sample:plant"};
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
