#pragma once
/// @file MapPainter.h (internal to src/output, not installed)
/// @brief Internal to src/output/MapRenderer*.cpp and MapCairo.cpp, not part of the public API: the map's page
/// layout, the cairo drawing primitives it shares (MapCairo.cpp), and MapPainter, which draws one MapRenderer in steps
/// (the plot area in MapRenderer.cpp, grid, frame and axes in MapRendererAxes.cpp, the legend in
/// MapRendererLegend.cpp).

#include <cmath>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include <cairo.h>

#include "ompl_glider/output/MapRenderer.h"
#include "../core/Numbers.h"

namespace ompl_glider
{
namespace map_detail
{
/// Page margins around the plot in pixels (the legend is drawn in the right margin).
constexpr double kLeft = 72, kRight = 270, kTop = 52, kBottom = 58;
/// Speed-shading values of the points without a current: land of the field (closed cells of a gridded forecast,
/// or wherever an analytic field has no water) and no data (outside a gridded forecast's grid).
constexpr double kLand = -1.0, kNoData = -2.0;
inline const Rgba kLandColour{0.80, 0.76, 0.68, 1.0}, kNoDataColour{0.90, 0.90, 0.92, 1.0};

/// A round step (1, 2, 5 x 10^k) at least @p raw; 1 for a raw step that is not positive and finite.
double niceStep(double raw);
/// A number for a label: @p prec decimals, or (prec < 0) as many as its magnitude needs, none for round values.
std::string fmt(double v, int prec = -1);
/// "76.50°W", "18.2°N": a longitude (east) or latitude (north) with as many decimals as @p step needs.
std::string degrees(double v, double step, bool east);

/// Sets the source colour.
void setColour(cairo_t *cr, const Rgba &c);
/// Sets the 6-4 dash of dashed lines when @p dashed (otherwise leaves the dash as it is).
void setDash(cairo_t *cr, bool dashed);
/// Text with a white halo so that it stays readable over lines and shading.
void haloText(cairo_t *cr, double x, double y, const std::string &s, const Rgba &c, double size, bool bold = false,
              double alignX = 0.0);
/// Text at (x, y) (baseline), aligned by @p alignX (0 left, 0.5 centre, 1 right).
void plainText(cairo_t *cr, double x, double y, const std::string &s, double size, bool bold = false,
               double alignX = 0.0, Rgba c = {0.1, 0.1, 0.1, 1.0});
/// Draws @p s left-aligned at (x, y), broken at spaces (or, for a single long word, at any character) so that no
/// line is wider than @p maxWidth; returns the number of lines drawn.
int wrappedText(cairo_t *cr, double x, double y, const std::string &s, double size, double maxWidth, double lineHeight,
                Rgba c = {0.1, 0.1, 0.1, 1.0});
/// The shading colour of a speed @p f in [0, 1] of the largest speed (very light blue to medium blue).
Rgba speedColour(double f);
/// An arrow from (x, y) by (dx, dy) pixels with a filled head of about @p head pixels, in the current source.
void arrow(cairo_t *cr, double x, double y, double dx, double dy, double head);
/// A waypoint marker: a white disc of @p radius outlined in @p colour.
void waypointMarker(cairo_t *cr, double x, double y, double radius, const Rgba &colour);
/// A new closed path: a five-pointed star centred at (cx, cy), tips at @p outer and notches at @p inner pixels.
void traceStar(cairo_t *cr, double cx, double cy, double outer, double inner);

/// Calls @p f(v) for v = the first multiple of @p step at or above @p lo, then v += step while v <= hi (+1e-9):
/// the grid lines, axis ticks and graticule lines.
template <class F> void forEachStep(double lo, double hi, double step, F &&f)
{
    for (double v = std::ceil(lo / step) * step; v <= hi + 1e-9; v += step)
        f(v);
}

/// Draws one MapRenderer on a cairo context: holds the page layout (pixel frame of the plot, grid steps) and what
/// the speed shading found for the legend. Made for one draw.
class MapPainter
{
public:
    MapPainter(const MapRenderer &map, cairo_t *context);
    /// A painter of a page @p height pixels tall (MapRenderer::size() measures the legend with it).
    MapPainter(const MapRenderer &map, cairo_t *context, int height);

    /// The legend drawn on the context as if the field's colour bar and its land and no-data entries were shown: the
    /// y of its bottom (pixels), at least what paint() draws.
    double legendBottom();

    /// The whole map: white page, the plot area (field, grid, forbidden regions, paths, start and goal) clipped to
    /// the plot, then frame and axes, then the legend.
    void paint();

    /// Pixel coordinates of field coordinates (x east, y north), aspect ratio 1:1.
    double X(double x) const { return kLeft + (x - region.xMin) * scale; }
    double Y(double y) const { return kTop + (region.yMax - y) * scale; }

    /// Moves to the first point and lines to the others (in pixels), on the current path.
    template <class Points> void tracePolyline(const Points &points) const
    {
        for (std::size_t k = 0; k < points.size(); ++k)
        {
            const double px = X(points[k].x), py = Y(points[k].y);
            k == 0 ? cairo_move_to(cr, px, py) : cairo_line_to(cr, px, py);
        }
    }

    const MapRenderer &map;
    const Region &region;
    const MapOptions &options;
    cairo_t *const cr;
    const int W, H;            ///< page size in pixels
    const double plotW, scale; ///< plot width in pixels, pixels per field unit
    const double plotH;        ///< plot height in pixels
    const double xs, ys;       ///< light-grid and axis-tick steps in field units
    const bool geographic;     ///< lon/lat graticule and labels instead of the x/y grid
    const std::string tu;      ///< " <time unit>" appended to times, or empty

private:
    // --- the plot area (MapRenderer.cpp)
    /// Samples the field's speed on cells of @p cell pixels (sets vmax_, landShown_, noDataShown_).
    std::vector<double> sampleSpeeds(int cell, int nx, int ny);
    /// Speed shading of the plot (when shown) from the sampled speeds.
    void drawSpeedShading();
    /// Current arrows on a grid of MapOptions::arrowColumns (when shown), scaled by the largest speed.
    void drawCurrentArrows() const;
    /// A forbidden region: filled, hatched when asked, outlined, labelled at its centroid.
    void drawRegion(const MapPolygon &poly) const;
    /// A path: white casing (solid lines), the line, waypoint markers and time ticks when @p ticks.
    void drawPath(const MapPath &p, bool ticks) const;
    /// The grid fill (MapGridFill): a cell about each node in fillColour() of its value.
    void drawGridFill() const;
    /// Measured currents (MapVectors) as arrows from their tails at arrowScale().
    void drawVectors() const;
    /// The pixels of a current arrow's cell (the arrows are at most 0.9 of it).
    double arrowCellPixels() const;
    /// Pixels per unit of speed of every arrow on the map: the current arrows' (0.9 cell at the largest speed of the
    /// field), or where the map draws none, the largest measured current's (0.9 cell); 0 when neither has a speed.
    double arrowScale() const;
    /// Time ticks across a path every MapOptions::tickInterval (or a round tenth of its duration), labelled.
    void drawTimeTicks(const MapPath &p) const;
    /// The start disc and the goal star, labelled.
    void drawStartGoal() const;
    void drawStations() const; ///< via points: marker, radius, name and arrival

    // --- grid, frame and axes (MapRendererAxes.cpp)
    /// The light x/y grid, or the graticule in a geographic frame, inside the plot.
    void drawGrid() const;
    /// Frame, axis ticks and names (or graticule labels and scale bar), and the title.
    void drawAxes() const;
    /// Graticule lines through the plot when @p lines; else their labels at the plot's edges and the scale bar.
    void drawGraticule(bool lines) const;
    /// A scale bar of a round number of km about a fifth of the width, bottom left inside the plot.
    void drawScaleBar() const;

    // --- the legend in the right margin (MapRendererLegend.cpp); each entry moves ly_ down
    void drawLegend();
    void drawPathEntries();
    void drawStartGoalEntries();
    /// The field's land and no-data areas (when shaded) and the forbidden regions (one entry per label).
    void drawAreaEntries();
    /// The current arrow (a key: a round speed at the arrows' scale) and the field's name, and the colour bar.
    void drawFieldEntries();
    /// Measured currents: their key arrow (a round speed at the arrows' scale) and label.
    void drawVectorEntries();
    /// The grid fill's colour bar from 0 to 1 and its label.
    void drawFillBar();
    /// A colour bar at the legend's place: kBarSteps boxes of @p colourOfStep(k), framed (the fill's and the speed's)
    void drawBar(const std::function<Rgba(int)> &colourOfStep);
    static constexpr int kBarSteps = 60;
    static constexpr double kBarWidth = 150.0, kBarHeight = 12.0;
    /// An arrow of a round speed (1, 2, 5 x 10^k at most @p top) at arrowScale() in the current source, from (lx_ + 2,
    /// ly_); returns the speed's text ("0.5 m/s (0.97 kn)").
    std::string keyArrow(double top);
    /// @p label from (x, ly_ + 4) wrapped to the page's right edge (a margin of 6 px): ly_ moves down by the extra
    /// lines' @p lineHeight.
    void legendLabel(double x, const std::string &label, double size, double lineHeight);
    void drawColourBar();
    /// The note on time ticks and the free text notes.
    void drawNotes();
    /// A filled swatch outlined in @p stroke, and its label.
    void legendSwatch(const Rgba &fill, const Rgba &stroke, double strokeWidth, const std::string &label);
    /// A position for the legend: degrees in a geographic frame, else the frame's x/y.
    std::string position(double x, double y) const;

    double vmax_{0.0};                           ///< largest current speed in the plot
    bool landShown_{false}, noDataShown_{false}; ///< the shading met land / no-data points
    double lx_{0.0}, ly_{0.0};                   ///< legend cursor
};
} // namespace map_detail
} // namespace ompl_glider
