// The toolbar's branch picker (issue 29): a combo box of the Bake nodes the editor can show
// (StudioModel::bakeNodes: every branch of the open scene), each named by its branch
// ("Cluster #5 → Bake #6"). Picking one shows that branch's HLOD (StudioModel::setShownBake),
// the same as clicking the Bake node in the Pipeline dock; it follows the shown node and the
// document (nodes added, removed, renamed). It holds no state of its own.
#pragma once

#include <QComboBox>

namespace hlod::widgets {

class ProjectSession;
class StudioModel;

class BranchBox : public QComboBox {
    Q_OBJECT
public:
    BranchBox(StudioModel* model, ProjectSession* session, QWidget* parent = nullptr);

    // Re-reads the Bake nodes and the shown one.
    void refresh();

private:
    StudioModel* model_;
    bool filling_ = false;
};

} // namespace hlod::widgets
