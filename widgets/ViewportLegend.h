// The colour legend in the viewport's overlay (issue 20 #6): what the colours of Clusters mode
// (one colour per cluster of the shown level) and of the HLOD preview's tint by depth (one
// colour per tree depth) mean, and the selection's highlight colour. Drawn in the bottom-right
// corner, or whichever free corner covers least of the scene (DisplayController picks it; issue
// 31 #9: fixed in the bottom-left it covered the scene; the counters' overlay takes the
// top-left): a square swatch and a line of text per
// entry on a dark, translucent box, painted with Qt (the application's font, sharp at any
// size) into an image that a VTK 2D actor shows; hidden without entries. It owns only its VTK
// prop; DisplayController says what to show.
#pragma once

#include <vector>

#include <QImage>
#include <QString>
#include <glm/glm.hpp>
#include <vtkSmartPointer.h>

class vtkActor2D;
class vtkCoordinate;
class vtkImageData;
class vtkRenderer;

namespace hlod::widgets {

class ViewportLegend {
public:
    struct Entry {
        QString text;
        glm::vec3 color{1.0f};
        bool swatch = true; // false: a heading line without a swatch
        bool operator==(const Entry&) const = default;
    };

    ViewportLegend();
    ~ViewportLegend();

    void addTo(vtkRenderer* renderer);
    void removeFrom(vtkRenderer* renderer);

    // Shows `entries` (none: hidden). At most kMaxEntries are shown. `scale`: device pixels per
    // logical pixel of the viewport.
    void setEntries(std::vector<Entry> entries, double scale = 1.0);
    const std::vector<Entry>& entries() const { return entries_; }
    bool visible() const;

    static constexpr int kMaxEntries = 10;

    // The corner it is drawn in; the top-left one is the counters' overlay's.
    enum class Corner { BottomRight, BottomLeft, TopRight };
    void setCorner(Corner corner);
    Corner corner() const { return corner_; }
    // The legend's size in device pixels (0 x 0 when hidden).
    QSize pixelSize() const { return image_.size(); }

    // The legend as painted (null image when hidden); for tests.
    const QImage& image() const { return image_; }

private:
    vtkSmartPointer<vtkActor2D> actor_;
    vtkSmartPointer<vtkImageData> pixels_;
    std::vector<Entry> entries_;
    double scale_ = 1.0;
    QImage image_;
    Corner corner_ = Corner::BottomRight;
    vtkSmartPointer<vtkCoordinate> reference_; // the corner, in normalized viewport units
    void place();
};

} // namespace hlod::widgets
