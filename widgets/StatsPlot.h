// A small live plot of draw calls and triangles per frame over the last seconds of navigation,
// painted with QPainter (two lines, each scaled to its own maximum, with the latest values).
//
// Samples: the plot keeps the latest frame's counters (setCurrent) and appends them to its
// history `sampleRate` times a second, so a still camera draws a flat line and a zoom through
// the HLOD shows its steps. Only the last `windowSeconds` are kept (a ring of samples). The
// history is display data only; the counters come from DisplayController::frameStats.
#pragma once

#include <cstdint>
#include <deque>

#include <QTimer>
#include <QWidget>

namespace hlod::widgets {

class StatsPlot : public QWidget {
    Q_OBJECT
public:
    explicit StatsPlot(QWidget* parent = nullptr, double windowSeconds = 10.0, int sampleRate = 10);

    void setCurrent(std::uint64_t drawCalls, std::uint64_t triangles);
    // Appends the current values as one sample (the timer calls this; tests call it directly).
    void sample();
    void clear();

    struct Sample {
        std::uint64_t drawCalls = 0;
        std::uint64_t triangles = 0;
    };
    const std::deque<Sample>& samples() const { return samples_; }
    std::size_t capacity() const { return capacity_; }

    QSize sizeHint() const override { return {320, 120}; }

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    std::deque<Sample> samples_;
    std::size_t capacity_;
    Sample current_;
    QTimer timer_;
};

} // namespace hlod::widgets
