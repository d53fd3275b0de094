// Test helper: writes a BREP file holding a single B-spline face with a dense control net, the
// shape of a terrain exported from CAD (one surface over a large extent, gentle hills plus
// per-pole noise). BRepMesh seeds a node on every knot line of such a face, so at the default
// deflection a 256 x 256 net costs it tens of seconds and gigabytes without a budget
// (issue 22); CadBudget.h bounds it.
//
// Deterministic: the noise comes from a fixed linear congruential sequence. Coordinates are in
// file units (the BREP unit option decides metres); the surface spans [0, extent]^2 in x, y.
#pragma once

#include <cmath>
#include <filesystem>
#include <stdexcept>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepTools.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Precision.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopoDS_Face.hxx>

namespace hlod::test {

inline void writeDenseBsplineBrep(const std::filesystem::path& file, int poles = 256,
                                  double extent = 10000.0) {
    constexpr int kDegree = 3;
    TColgp_Array2OfPnt net(1, poles, 1, poles);
    unsigned seed = 12345u;
    for (int i = 1; i <= poles; ++i) {
        for (int j = 1; j <= poles; ++j) {
            const double x = extent * (i - 1) / (poles - 1), y = extent * (j - 1) / (poles - 1);
            seed = seed * 1664525u + 1013904223u;
            const double noise = static_cast<double>((seed >> 8) & 0xffffu) / 65535.0 - 0.5;
            const double hills = std::sin(x / extent * 17.0) * std::cos(y / extent * 13.0);
            net(i, j) = gp_Pnt(x, y, 0.03 * extent * hills + 0.01 * extent * noise);
        }
    }
    // Uniform clamped knots: end multiplicities degree + 1, single interior knots.
    const int knots = poles - kDegree + 1;
    TColStd_Array1OfReal values(1, knots);
    TColStd_Array1OfInteger mults(1, knots);
    for (int k = 1; k <= knots; ++k) {
        values(k) = k - 1;
        mults(k) = 1;
    }
    mults(1) = mults(knots) = kDegree + 1;
    const Handle(Geom_BSplineSurface) surface =
        new Geom_BSplineSurface(net, values, values, mults, mults, kDegree, kDegree);
    BRepBuilderAPI_MakeFace face(surface, Precision::Confusion());
    if (!face.IsDone() || !BRepTools::Write(face.Face(), file.string().c_str())) {
        throw std::runtime_error("cannot write " + file.string());
    }
}

} // namespace hlod::test
