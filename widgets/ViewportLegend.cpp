// The colour legend of the viewport overlay (see ViewportLegend.h).
#include "widgets/ViewportLegend.h"

#include <algorithm>
#include <cstring>

#include <QApplication>
#include <QFontMetrics>
#include <QPainter>
#include <vtkActor2D.h>
#include <vtkCoordinate.h>
#include <vtkImageData.h>
#include <vtkImageMapper.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkRenderer.h>
#include <vtkUnsignedCharArray.h>

namespace hlod::widgets {

namespace {

constexpr int kMargin = 8;  // from the viewport's corner, logical pixels
constexpr int kPadding = 6; // inside the box
constexpr int kSwatch = 12;

QColor toQColor(const glm::vec3& c) { return QColor::fromRgbF(c.r, c.g, c.b); }

// The legend box: swatches and lines of text on the overlay's dark translucent background.
QImage paintLegend(const std::vector<ViewportLegend::Entry>& entries, double scale) {
    QFont font = QApplication::font();
    font.setPixelSize(13);
    const QFontMetrics metrics(font);
    const int line = std::max(metrics.height(), kSwatch) + 3;
    int width = 0;
    for (const ViewportLegend::Entry& e : entries)
        width = std::max(width, metrics.horizontalAdvance(e.text) + (e.swatch ? kSwatch + 6 : 0));
    const QSize logical(width + 2 * kPadding,
                        line * static_cast<int>(entries.size()) + 2 * kPadding - 3);
    QImage image(logical * scale, QImage::Format_RGBA8888);
    image.setDevicePixelRatio(scale);
    image.fill(QColor::fromRgbF(0.1, 0.12, 0.16, 0.65));
    QPainter painter(&image);
    painter.setFont(font);
    painter.setRenderHint(QPainter::Antialiasing);
    int y = kPadding;
    for (const ViewportLegend::Entry& e : entries) {
        int x = kPadding;
        if (e.swatch) {
            const QRect box(x, y + (line - 3 - kSwatch) / 2, kSwatch, kSwatch);
            painter.fillRect(box, toQColor(e.color));
            painter.setPen(QColor(255, 255, 255, 140));
            painter.drawRect(box);
            x += kSwatch + 6;
        }
        painter.setPen(e.swatch ? Qt::white : QColor(220, 225, 235));
        painter.drawText(QRect(x, y, width, line - 3), Qt::AlignLeft | Qt::AlignVCenter, e.text);
        y += line;
    }
    painter.end();
    return image;
}

} // namespace

ViewportLegend::ViewportLegend()
    : actor_(vtkSmartPointer<vtkActor2D>::New()), pixels_(vtkSmartPointer<vtkImageData>::New()) {
    vtkNew<vtkImageMapper> mapper;
    mapper->SetInputData(pixels_);
    mapper->SetColorWindow(255.0); // the image's bytes as they are
    mapper->SetColorLevel(127.5);
    actor_->SetMapper(mapper);
    // Placed at an offset in pixels from a corner of the viewport (place()).
    reference_ = vtkSmartPointer<vtkCoordinate>::New();
    reference_->SetCoordinateSystemToNormalizedViewport();
    actor_->GetPositionCoordinate()->SetCoordinateSystemToDisplay();
    actor_->GetPositionCoordinate()->SetReferenceCoordinate(reference_);
    actor_->PickableOff();
    actor_->VisibilityOff();
}

ViewportLegend::~ViewportLegend() = default;

void ViewportLegend::addTo(vtkRenderer* renderer) { renderer->AddViewProp(actor_); }

void ViewportLegend::removeFrom(vtkRenderer* renderer) { renderer->RemoveViewProp(actor_); }

bool ViewportLegend::visible() const { return actor_->GetVisibility() != 0; }

void ViewportLegend::setEntries(std::vector<Entry> entries, double scale) {
    if (entries.size() > static_cast<std::size_t>(kMaxEntries)) entries.resize(kMaxEntries);
    if (entries == entries_ && scale == scale_) return;
    entries_ = std::move(entries);
    scale_ = scale;
    actor_->SetVisibility(!entries_.empty());
    if (entries_.empty()) {
        image_ = QImage();
        return;
    }
    image_ = paintLegend(entries_, scale_);
    // VTK's rows run bottom-up.
    const QImage flipped = image_.mirrored(false, true);
    const int w = flipped.width(), h = flipped.height();
    pixels_->SetDimensions(w, h, 1);
    pixels_->AllocateScalars(VTK_UNSIGNED_CHAR, 4);
    auto* out = static_cast<unsigned char*>(pixels_->GetScalarPointer());
    for (int row = 0; row < h; ++row)
        std::memcpy(out + static_cast<std::size_t>(row) * w * 4, flipped.constScanLine(row),
                    static_cast<std::size_t>(w) * 4);
    pixels_->Modified();
    place();
}

void ViewportLegend::setCorner(Corner corner) {
    if (corner == corner_) return;
    corner_ = corner;
    place();
}

void ViewportLegend::place() {
    const double w = image_.width(), h = image_.height(), m = kMargin * scale_;
    const bool right = corner_ != Corner::BottomLeft;
    const bool top = corner_ == Corner::TopRight;
    reference_->SetValue(right ? 1.0 : 0.0, top ? 1.0 : 0.0);
    actor_->SetPosition(right ? -w - m : m, top ? -h - m : m);
}

} // namespace hlod::widgets
