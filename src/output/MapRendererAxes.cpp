/// @file MapRendererAxes.cpp
/// @brief The map's grid, frame and axes: the light x/y grid and axis ticks, or in a geographic frame the graticule
/// of meridians and parallels, its labels and a scale bar (MapRenderer's drawing, see src/output/MapPainter.h).

#include <algorithm>
#include <cmath>
#include <vector>

#include <cairo.h>

#include "ompl_glider/io/GeoBox.h"
#include "MapPainter.h"

namespace ompl_glider
{
namespace map_detail
{
namespace
{
/// A graticule step in degrees giving about `lines` lines over `span` degrees.
double degreeStep(double span, double lines)
{
    for (double s : {0.01, 0.02, 0.05, 0.1, 0.2, 0.25, 0.5, 1.0, 2.0, 5.0, 10.0, 15.0, 30.0})
        if (span / s <= lines)
            return s;
    return 45.0;
}

/// The lon/lat extent of the plot and the step of its meridians and parallels.
struct Graticule
{
    Graticule(const Region &reg, const MapOptions &o) : options(o)
    {
        const GeoBox gb = frameBounds(Box{reg.xMin, reg.xMax, reg.yMin, reg.yMax}, o.toGeographic);
        lon0 = gb.lonMin;
        lon1 = gb.lonMax;
        lat0 = gb.latMin;
        lat1 = gb.latMax;
        if (!empty())
            step = degreeStep(std::max(lon1 - lon0, lat1 - lat0), 7.0);
    }

    bool empty() const { return !(lon1 > lon0) || !(lat1 > lat0); }

    /// The meridian (longitude @p v) or parallel (latitude @p v) across the extent, in the field's frame.
    std::vector<Point2> line(bool meridian, double v) const
    {
        const int n = 80;
        std::vector<Point2> pts;
        for (int k = 0; k <= n; ++k)
        {
            const double s = k / double(n);
            const LonLat g = meridian ? LonLat{v, lat0 + s * (lat1 - lat0)} : LonLat{lon0 + s * (lon1 - lon0), v};
            pts.push_back(options.toLocal(g));
        }
        return pts;
    }

    /// Calls @p f(meridian, v) for the meridians, then the parallels, on the step.
    template <class F> void forEachLine(F &&f) const
    {
        for (int meridian = 0; meridian < 2; ++meridian)
            forEachStep(meridian ? lon0 : lat0, meridian ? lon1 : lat1, step, [&](double v) { f(meridian, v); });
    }

    const MapOptions &options;
    double lon0, lon1, lat0, lat1;
    double step{1.0};
};

/// The label of a meridian where it leaves the plot at the bottom edge, or of a parallel at the left edge, with a
/// tick (nothing when it does not cross that edge within the plot).
void graticuleLabel(const MapPainter &p, const Graticule &g, bool meridian, double v)
{
    const Region &reg = p.region;
    cairo_t *cr = p.cr;
    const auto pts = g.line(meridian, v);
    for (std::size_t k = 0; k + 1 < pts.size(); ++k)
    {
        const Point2 a = pts[k], b = pts[k + 1];
        if (meridian && (a.y - reg.yMin) * (b.y - reg.yMin) <= 0 && a.y != b.y)
        {
            const double x = a.x + (reg.yMin - a.y) / (b.y - a.y) * (b.x - a.x);
            if (x < reg.xMin || x > reg.xMax)
                continue;
            cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
            cairo_move_to(cr, p.X(x), p.Y(reg.yMin));
            cairo_line_to(cr, p.X(x), p.Y(reg.yMin) + 5);
            cairo_stroke(cr);
            plainText(cr, p.X(x), p.Y(reg.yMin) + 19, degrees(v, g.step, true), 12, false, 0.5);
            return;
        }
        if (!meridian && (a.x - reg.xMin) * (b.x - reg.xMin) <= 0 && a.x != b.x)
        {
            const double y = a.y + (reg.xMin - a.x) / (b.x - a.x) * (b.y - a.y);
            if (y < reg.yMin || y > reg.yMax)
                continue;
            cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
            cairo_move_to(cr, p.X(reg.xMin) - 5, p.Y(y));
            cairo_line_to(cr, p.X(reg.xMin), p.Y(y));
            cairo_stroke(cr);
            plainText(cr, p.X(reg.xMin) - 8, p.Y(y) + 4, degrees(v, g.step, false), 12, false, 1.0);
            return;
        }
    }
}
} // namespace

void MapPainter::drawGrid() const
{
    cairo_set_source_rgba(cr, 0.3, 0.3, 0.3, 0.18);
    cairo_set_line_width(cr, 0.8);
    if (geographic)
        drawGraticule(true);
    else
    {
        forEachStep(region.xMin, region.xMax, xs, [&](double x) {
            cairo_move_to(cr, X(x), kTop);
            cairo_line_to(cr, X(x), kTop + plotH);
        });
        forEachStep(region.yMin, region.yMax, ys, [&](double y) {
            cairo_move_to(cr, kLeft, Y(y));
            cairo_line_to(cr, kLeft + plotW, Y(y));
        });
    }
    cairo_stroke(cr);
}

void MapPainter::drawAxes() const
{
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    cairo_set_line_width(cr, 1.2);
    cairo_rectangle(cr, kLeft, kTop, plotW, plotH);
    cairo_stroke(cr);
    if (geographic)
        drawGraticule(false);
    else
    {
        forEachStep(region.xMin, region.xMax, xs, [&](double x) {
            cairo_move_to(cr, X(x), kTop + plotH);
            cairo_line_to(cr, X(x), kTop + plotH + 5);
            cairo_stroke(cr);
            plainText(cr, X(x), kTop + plotH + 19, fmt(std::abs(x) < 1e-12 ? 0.0 : x), 12, false, 0.5);
        });
        forEachStep(region.yMin, region.yMax, ys, [&](double y) {
            cairo_move_to(cr, kLeft - 5, Y(y));
            cairo_line_to(cr, kLeft, Y(y));
            cairo_stroke(cr);
            plainText(cr, kLeft - 8, Y(y) + 4, fmt(std::abs(y) < 1e-12 ? 0.0 : y), 12, false, 1.0);
        });
    }
    plainText(cr, kLeft + plotW / 2, kTop + plotH + 42, geographic ? "longitude" : "x (east)", 13, true, 0.5);
    cairo_save(cr);
    cairo_move_to(cr, 0, 0);
    cairo_translate(cr, 22, kTop + plotH / 2);
    cairo_rotate(cr, -kPi / 2);
    plainText(cr, 0, 0, geographic ? "latitude" : "y (north)", 13, true, 0.5);
    cairo_restore(cr);
    if (!options.title.empty())
        plainText(cr, kLeft, 32, options.title, 17, true);
}

void MapPainter::drawGraticule(bool lines) const
{
    const Graticule g(region, options);
    if (g.empty())
        return;
    if (lines)
    {
        cairo_save(cr);
        cairo_rectangle(cr, X(region.xMin), Y(region.yMax), X(region.xMax) - X(region.xMin),
                        Y(region.yMin) - Y(region.yMax));
        cairo_clip(cr);
        cairo_set_source_rgba(cr, 0.25, 0.25, 0.25, 0.45);
        cairo_set_line_width(cr, 0.7);
        g.forEachLine([&](bool meridian, double v) {
            tracePolyline(g.line(meridian, v));
            cairo_stroke(cr);
        });
        cairo_restore(cr);
        return;
    }
    g.forEachLine([&](bool meridian, double v) { graticuleLabel(*this, g, meridian, v); });
    if (options.metresPerUnit > 0.0)
        drawScaleBar();
}

void MapPainter::drawScaleBar() const
{
    const double widthKm = (region.xMax - region.xMin) * options.metresPerUnit / 1000.0;
    const double raw = widthKm / 5.0, p = std::pow(10.0, std::floor(std::log10(raw))), m = raw / p;
    const double km = p * (m < 2.0 ? 1.0 : m < 5.0 ? 2.0 : 5.0);
    const double len = km * 1000.0 / options.metresPerUnit;
    const double x0 = X(region.xMin) + 16, y0 = Y(region.yMin) - 16, x1 = x0 + (X(region.xMin + len) - X(region.xMin));
    cairo_set_source_rgba(cr, 1, 1, 1, 0.75);
    cairo_rectangle(cr, x0 - 6, y0 - 20, x1 - x0 + 12, 28);
    cairo_fill(cr);
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    cairo_set_line_width(cr, 2.0);
    cairo_move_to(cr, x0, y0 - 4);
    cairo_line_to(cr, x0, y0);
    cairo_line_to(cr, x1, y0);
    cairo_line_to(cr, x1, y0 - 4);
    cairo_stroke(cr);
    plainText(cr, 0.5 * (x0 + x1), y0 - 7, fmt(km) + " km", 11, false, 0.5);
}
} // namespace map_detail
} // namespace ompl_glider
