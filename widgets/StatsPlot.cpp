// Live plot of draw calls and triangles (see StatsPlot.h).
#include "widgets/StatsPlot.h"

#include <algorithm>

#include <QLocale>
#include <QPainter>
#include <QPainterPath>

namespace hlod::widgets {

namespace {

const QColor kDrawCallColor(64, 140, 230);
const QColor kTriangleColor(235, 130, 40);

} // namespace

StatsPlot::StatsPlot(QWidget* parent, double windowSeconds, int sampleRate)
    : QWidget(parent),
      capacity_(static_cast<std::size_t>(std::max(2.0, windowSeconds * sampleRate))) {
    setMinimumHeight(90);
    timer_.setInterval(1000 / std::max(sampleRate, 1));
    connect(&timer_, &QTimer::timeout, this, [this] {
        if (isVisible()) sample();
    });
    timer_.start();
}

void StatsPlot::setCurrent(std::uint64_t drawCalls, std::uint64_t triangles) {
    current_ = {drawCalls, triangles};
}

void StatsPlot::sample() {
    samples_.push_back(current_);
    while (samples_.size() > capacity_)
        samples_.pop_front();
    update();
}

void StatsPlot::clear() {
    samples_.clear();
    current_ = {};
    update();
}

void StatsPlot::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    p.fillRect(rect(), palette().base());
    const QRectF area = QRectF(rect()).adjusted(6, 22, -6, -6);
    p.setPen(QPen(palette().mid().color(), 1, Qt::DashLine));
    p.drawRect(area);
    const QLocale locale;
    p.setPen(kDrawCallColor);
    p.drawText(
        QPointF(6, 15),
        tr("draw calls %1").arg(locale.toString(static_cast<qulonglong>(current_.drawCalls))));
    p.setPen(kTriangleColor);
    p.drawText(
        QRectF(0, 2, width() - 6, 18), Qt::AlignRight | Qt::AlignVCenter,
        tr("triangles %1").arg(locale.toString(static_cast<qulonglong>(current_.triangles))));
    if (samples_.size() < 2) return;

    // Each series against its own maximum: they differ by orders of magnitude.
    auto series = [&](auto value, const QColor& color) {
        std::uint64_t top = 1;
        for (const Sample& s : samples_)
            top = std::max(top, value(s));
        QPainterPath path;
        const double step = area.width() / double(capacity_ - 1);
        // Newest sample at the right edge; older ones scroll left.
        const double x0 = area.right() - step * double(samples_.size() - 1);
        for (std::size_t i = 0; i < samples_.size(); ++i) {
            const double y = area.bottom() - area.height() * double(value(samples_[i])) / top;
            const QPointF point(x0 + step * double(i), y);
            if (i == 0)
                path.moveTo(point);
            else
                path.lineTo(point);
        }
        p.setPen(QPen(color, 1.6));
        p.drawPath(path);
    };
    series([](const Sample& s) { return s.triangles; }, kTriangleColor);
    series([](const Sample& s) { return s.drawCalls; }, kDrawCallColor);
}

} // namespace hlod::widgets
