// The toolbar's branch picker (see BranchBox.h).
#include "widgets/BranchBox.h"

#include "widgets/StudioModel.h"
#include "widgets/doc/ProjectSession.h"

namespace hlod::widgets {

BranchBox::BranchBox(StudioModel* model, ProjectSession* session, QWidget* parent)
    : QComboBox(parent), model_(model) {
    setObjectName(QStringLiteral("BranchBox"));
    setToolTip(tr("The branch whose HLOD the view, the Clusters tab and Statistics show (also: "
                  "click its Bake node in the Pipeline dock)"));
    setSizeAdjustPolicy(QComboBox::AdjustToContents);
    connect(this, &QComboBox::currentIndexChanged, this, [this] {
        if (filling_ || currentIndex() < 0) return;
        model_->setShownBake(currentData().value<quint32>());
    });
    connect(model_, &StudioModel::shownBakeChanged, this, &BranchBox::refresh);
    connect(model_, &StudioModel::sceneChanged, this, &BranchBox::refresh);
    connect(session, &ProjectSession::documentChanged, this, &BranchBox::refresh);
    refresh();
}

void BranchBox::refresh() {
    filling_ = true;
    clear();
    for (NodeId bake : model_->bakeNodes())
        addItem(model_->branchLabel(bake), QVariant::fromValue<quint32>(bake));
    setCurrentIndex(findData(QVariant::fromValue<quint32>(model_->shownBake())));
    setEnabled(count() > 0);
    filling_ = false;
}

} // namespace hlod::widgets
