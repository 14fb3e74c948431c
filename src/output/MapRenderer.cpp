/// @file MapRenderer.cpp
/// @brief MapRenderer's API and file writing, and the plot area of the map (speed shading, current arrows, forbidden
/// regions, paths, start and goal). The cairo drawing primitives shared by the maps and plots, and the writing of a
/// drawing as a file: MapCairo.cpp; grid and axes: MapRendererAxes.cpp; legend: MapRendererLegend.cpp.
#include "ompl_glider/output/MapRenderer.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <cairo.h>

#include "ompl_glider/Exception.h"
#include "ompl_glider/current/CurrentField.h"
#include "MapPainter.h"

namespace ompl_glider
{
namespace map_detail
{
MapPainter::MapPainter(const MapRenderer &m, cairo_t *context) : MapPainter(m, context, m.size().second) {}

MapPainter::MapPainter(const MapRenderer &m, cairo_t *context, int height)
    : map(m), region(m.region_), options(m.options_), cr(context), W(m.options_.width), H(height),
      plotW(W - kLeft - kRight), scale(plotW / (region.xMax - region.xMin)), plotH(scale * (region.yMax - region.yMin)),
      xs(niceStep((region.xMax - region.xMin) / 8)), ys(niceStep((region.yMax - region.yMin) / 8)),
      geographic(options.toGeographic && options.toLocal), tu(options.timeUnit.empty() ? "" : " " + options.timeUnit)
{
}

void MapPainter::paint()
{
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);

    // --- the plot area: field, grid, forbidden regions, paths, start and goal, clipped to the plot
    cairo_save(cr);
    cairo_rectangle(cr, kLeft, kTop, plotW, plotH);
    cairo_clip(cr);
    if (map.field_)
        drawSpeedShading();
    drawGridFill();
    if (map.field_)
        drawCurrentArrows();
    drawGrid();
    for (const MapPolygon &poly : map.polygons_)
        drawRegion(poly);
    // one tick series: the last path that asks for ticks gets them
    const MapPath *ticked = nullptr;
    for (const MapPath &p : map.paths_)
        ticked = p.timeTicks && p.waypoints.size() >= 2 && std::isfinite(p.waypoints.back().t) ? &p : ticked;
    for (const MapPath &p : map.paths_)
        drawPath(p, &p == ticked);
    drawVectors();
    drawStations();
    if (map.hasStartGoal_)
        drawStartGoal();
    cairo_restore(cr);

    drawAxes();
    drawLegend();
}

std::vector<double> MapPainter::sampleSpeeds(int cell, int nx, int ny)
{
    const CurrentField &field = *map.field_;
    const double depth = map.fieldDepth_, time = map.fieldTime_;
    std::vector<double> sp(static_cast<std::size_t>(nx) * ny, 0.0);
    // a gridded forecast tells land (closed nodes of its grid) from no data (outside its grid)
    const FieldGrid *grid = field.grid();
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i)
        {
            const double x = region.xMin + (i + 0.5) * cell / scale, y = region.yMax - (j + 0.5) * cell / scale;
            double s = 0.0;
            if (field.inWater(x, y, depth))
            {
                const Velocity c = field.velocity(x, y, depth, time);
                s = std::hypot(c.u, c.v);
                if (!std::isfinite(s))
                    s = 0.0;
            }
            else
            {
                s = grid && !grid->covers(x, y) ? kNoData : kLand;
                (s == kLand ? landShown_ : noDataShown_) = true;
            }
            sp[static_cast<std::size_t>(j) * nx + i] = s;
            vmax_ = std::max(vmax_, s);
        }
    return sp;
}

void MapPainter::drawSpeedShading()
{
    const int cell = 6;
    const int nx = static_cast<int>(std::ceil(plotW / cell)), ny = static_cast<int>(std::ceil(plotH / cell));
    const std::vector<double> sp = sampleSpeeds(cell, nx, ny);
    if (!options.speedShading)
        return;
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i)
        {
            const double s = sp[static_cast<std::size_t>(j) * nx + i];
            setColour(cr, s == kLand     ? kLandColour
                          : s == kNoData ? kNoDataColour
                                         : speedColour(vmax_ > 0 ? s / vmax_ : 0.0));
            cairo_rectangle(cr, kLeft + i * cell, kTop + j * cell, cell + 0.5, cell + 0.5);
            cairo_fill(cr);
        }
}

double MapPainter::arrowCellPixels() const
{
    const int cols = options.arrowColumns;
    const double dxCell = (region.xMax - region.xMin) / cols;
    const int rows = std::max(2, static_cast<int>(std::round((region.yMax - region.yMin) / dxCell)));
    const double dyCell = (region.yMax - region.yMin) / rows;
    return std::min(dxCell, dyCell) * scale;
}

double MapPainter::arrowScale() const
{
    if (map.field_ && options.arrows && vmax_ > 0.0)
        return 0.9 * arrowCellPixels() / vmax_;
    double fastest = 0.0;
    for (const MapVectors &v : map.vectors_)
        for (const Velocity &c : v.velocity)
            fastest = std::max(fastest, std::hypot(c.u, c.v));
    return fastest > 0.0 && std::isfinite(fastest) ? 0.9 * arrowCellPixels() / fastest : 0.0;
}

void MapPainter::drawVectors() const
{
    const double k = arrowScale();
    for (const MapVectors &v : map.vectors_)
    {
        setColour(cr, v.colour);
        cairo_set_line_width(cr, 1.6);
        for (std::size_t i = 0; i < v.at.size(); ++i)
        {
            const double len = k * std::hypot(v.velocity[i].u, v.velocity[i].v);
            if (!(len > 0.0) || !std::isfinite(len))
                continue;
            arrow(cr, X(v.at[i].x), Y(v.at[i].y), k * v.velocity[i].u, -k * v.velocity[i].v,
                  std::min(7.0, 0.35 * len + 2.0));
        }
    }
}

void MapPainter::drawGridFill() const
{
    if (!map.fill_)
        return;
    // one pixel a node (its centre at the node), drawn scaled with bilinear filtering: seamless, and a node's colour
    // is fillColour() of its value
    const MapGridFill &f = *map.fill_;
    cairo_surface_t *img = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, f.nx, f.ny);
    unsigned char *data = cairo_image_surface_get_data(img);
    const int stride = cairo_image_surface_get_stride(img);
    for (int j = 0; j < f.ny; ++j)
        for (int i = 0; i < f.nx; ++i)
        {
            const double p = f.values[static_cast<std::size_t>(j) * f.nx + i];
            const Rgba c = p > 0.0 ? fillColour(p) : Rgba{0.0, 0.0, 0.0, 0.0};
            const auto byte = [](double v) { return static_cast<std::uint32_t>(std::lround(255.0 * v)); };
            // premultiplied ARGB, row 0 at the top (the grid's last row of nodes)
            *reinterpret_cast<std::uint32_t *>(data + (f.ny - 1 - j) * stride + 4 * i) =
                byte(c.a) << 24 | byte(c.r * c.a) << 16 | byte(c.g * c.a) << 8 | byte(c.b * c.a);
        }
    cairo_surface_mark_dirty(img);
    cairo_save(cr);
    cairo_translate(cr, X(f.x0 - 0.5 * f.h), Y(f.y0 + (f.ny - 0.5) * f.h));
    cairo_scale(cr, f.h * scale, f.h * scale);
    cairo_set_source_surface(cr, img, 0, 0);
    cairo_pattern_set_filter(cairo_get_source(cr), CAIRO_FILTER_BILINEAR);
    cairo_rectangle(cr, 0, 0, f.nx, f.ny);
    cairo_fill(cr);
    cairo_restore(cr);
    cairo_surface_destroy(img);
}

void MapPainter::drawCurrentArrows() const
{
    const CurrentField &field = *map.field_;
    const int cols = options.arrows ? options.arrowColumns : 0;
    const double dxCell = (region.xMax - region.xMin) / cols;
    const int rows = cols == 0 ? 0 : std::max(2, static_cast<int>(std::round((region.yMax - region.yMin) / dxCell)));
    const double dyCell = (region.yMax - region.yMin) / rows;
    const double k = arrowScale(); // pixels per unit of speed
    cairo_set_source_rgba(cr, 0.10, 0.20, 0.40, 0.75);
    cairo_set_line_width(cr, 1.1);
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < cols; ++i)
        {
            const double x = region.xMin + (i + 0.5) * dxCell, y = region.yMin + (j + 0.5) * dyCell;
            if (!field.inWater(x, y, map.fieldDepth_))
                continue;
            const Velocity c = field.velocity(x, y, map.fieldDepth_, map.fieldTime_);
            const double s = std::hypot(c.u, c.v);
            if (!(s > 0.0) || !std::isfinite(s) || !(vmax_ > 0))
                continue;
            const double len = k * s;
            if (len < 2.0)
                continue;
            const double cx = X(x) - 0.5 * len * c.u / s, cy = Y(y) + 0.5 * len * c.v / s;
            arrow(cr, cx, cy, len * c.u / s, -len * c.v / s, std::min(6.0, 0.35 * len + 2.0));
        }
}

void MapPainter::drawRegion(const MapPolygon &poly) const
{
    auto outline = [&] {
        cairo_new_path(cr);
        tracePolyline(poly.vertices);
        cairo_close_path(cr);
    };
    outline();
    setColour(cr, poly.fill);
    cairo_fill_preserve(cr);
    if (poly.hatched)
    {
        cairo_save(cr);
        cairo_clip_preserve(cr);
        cairo_set_source_rgba(cr, poly.stroke.r, poly.stroke.g, poly.stroke.b, 0.6);
        cairo_set_line_width(cr, 1.0);
        for (double d = -H; d < W + H; d += 9)
        {
            cairo_move_to(cr, d, 0);
            cairo_line_to(cr, d + H, H);
        }
        cairo_stroke(cr);
        cairo_restore(cr);
        outline(); // restore the polygon outline path for the stroke below
    }
    setColour(cr, poly.stroke);
    cairo_set_line_width(cr, 1.5);
    cairo_stroke(cr);
    if (!poly.label.empty())
    {
        double cx = 0, cy = 0;
        for (const auto &v : poly.vertices)
        {
            cx += v.x;
            cy += v.y;
        }
        cx /= poly.vertices.size();
        cy /= poly.vertices.size();
        haloText(cr, X(cx), Y(cy) + 4, poly.label, poly.stroke, 12, true, 0.5); // (a coastline's have none)
    }
}

void MapPainter::drawPath(const MapPath &p, bool ticks) const
{
    cairo_new_path(cr);
    tracePolyline(p.waypoints);
    // white casing keeps the line visible over arrows
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
    if (!p.dashed)
    {
        cairo_set_source_rgba(cr, 1, 1, 1, 0.8);
        cairo_set_line_width(cr, p.width + 2.5);
        cairo_stroke_preserve(cr);
    }
    setColour(cr, p.colour);
    cairo_set_line_width(cr, p.width);
    setDash(cr, p.dashed);
    cairo_stroke(cr);
    cairo_set_dash(cr, nullptr, 0, 0);
    if (p.waypointMarkers)
        for (const TimedPoint &w : p.waypoints)
            waypointMarker(cr, X(w.x), Y(w.y), p.width + 1.2, p.colour);
    if (ticks)
        drawTimeTicks(p);
}

void MapPainter::drawTimeTicks(const MapPath &p) const
{
    const double tA = p.waypoints.front().t, tB = p.waypoints.back().t;
    const double step = options.tickInterval > 0 ? options.tickInterval : niceStep((tB - tA) / 10);
    std::size_t leg = 1;
    for (double T = (std::floor(tA / step) + 1) * step; T < tB - 1e-9 * step; T += step)
    {
        while (leg + 1 < p.waypoints.size() && p.waypoints[leg].t < T)
            ++leg;
        const TimedPoint &a = p.waypoints[leg - 1], &b = p.waypoints[leg];
        const double f = b.t > a.t ? std::clamp((T - a.t) / (b.t - a.t), 0.0, 1.0) : 0.0;
        const double x = X(a.x + f * (b.x - a.x)), y = Y(a.y + f * (b.y - a.y));
        double nx = -(Y(b.y) - Y(a.y)), ny = X(b.x) - X(a.x);
        const double nl = std::hypot(nx, ny);
        if (nl > 0)
        {
            nx /= nl;
            ny /= nl;
        }
        setColour(cr, p.colour);
        cairo_set_line_width(cr, 2.0);
        cairo_move_to(cr, x - 7 * nx, y - 7 * ny);
        cairo_line_to(cr, x + 7 * nx, y + 7 * ny);
        cairo_stroke(cr);
        // label on the side that points up/left, away from the track
        const double side = ny > 0 ? -1.0 : 1.0;
        const std::string label = options.tickUnit.empty() ? "t=" + fmt(T) + tu : "+" + fmt(T) + " " + options.tickUnit;
        haloText(cr, x + side * 16 * nx, y + side * 16 * ny + 4, label, {0.1, 0.1, 0.1, 1}, 11, false, 0.5);
    }
}

void MapPainter::drawStations() const
{
    for (const auto &st : map.stations_)
    {
        const double x = X(st.at.x), y = Y(st.at.y), r = std::max(7.0, st.radius * scale);
        cairo_new_path(cr);
        cairo_arc(cr, x, y, r, 0, 2 * kPi);
        cairo_set_source_rgba(cr, 0.95, 0.55, 0.0, 0.9);
        cairo_set_line_width(cr, 1.5);
        cairo_stroke(cr);
        cairo_rectangle(cr, x - 4.5, y - 4.5, 9, 9);
        cairo_set_source_rgb(cr, 0.95, 0.55, 0.0);
        cairo_fill_preserve(cr);
        cairo_set_source_rgb(cr, 1, 1, 1);
        cairo_set_line_width(cr, 1.2);
        cairo_stroke(cr);
        haloText(cr, x + 10, y + 14, st.label, {0.55, 0.30, 0.0, 1}, 11, true);
    }
}

void MapPainter::drawStartGoal() const
{
    cairo_new_path(cr);
    cairo_arc(cr, X(map.sx_), Y(map.sy_), 8, 0, 2 * kPi);
    cairo_set_source_rgb(cr, 0.05, 0.60, 0.15);
    cairo_fill_preserve(cr);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_set_line_width(cr, 2);
    cairo_stroke(cr);
    haloText(cr, X(map.sx_) + 11, Y(map.sy_) - 9, "START", {0.05, 0.45, 0.1, 1}, 13, true);
    const double gxp = X(map.gx_), gyp = Y(map.gy_);
    traceStar(cr, gxp, gyp, 11.0, 4.5);
    cairo_set_source_rgb(cr, 0.55, 0.0, 0.55);
    cairo_fill_preserve(cr);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_set_line_width(cr, 1.5);
    cairo_stroke(cr);
    haloText(cr, gxp + 12, gyp - 10, "GOAL", {0.45, 0.0, 0.45, 1}, 13, true);
}
} // namespace map_detail

using map_detail::kBottom;
using map_detail::kLeft;
using map_detail::kRight;
using map_detail::kTop;

namespace
{
/// A path in a given style (the other MapPath fields keep their defaults).
MapPath styledPath(std::string label, std::vector<TimedPoint> waypoints, Rgba colour, double width, bool dashed,
                   bool waypointMarkers, bool timeTicks)
{
    MapPath p;
    p.label = std::move(label);
    p.waypoints = std::move(waypoints);
    p.colour = colour;
    p.width = width;
    p.dashed = dashed;
    p.waypointMarkers = waypointMarkers;
    p.timeTicks = timeTicks;
    return p;
}
} // namespace

MapRenderer::MapRenderer(const Region &region, MapOptions options) : region_(region), options_(std::move(options))
{
    if (!std::isfinite(region_.xMin) || !std::isfinite(region_.xMax) || !std::isfinite(region_.yMin) ||
        !std::isfinite(region_.yMax) || !(region_.xMax > region_.xMin) || !(region_.yMax > region_.yMin))
        throw Error("MapRenderer: the region's x/y bounds must be finite with xMin < xMax and yMin < yMax");
    if (options_.width < 400)
        throw Error("MapRenderer: width must be >= 400 pixels (got " + std::to_string(options_.width) + ")");
    if (options_.arrowColumns < 2)
        options_.arrowColumns = 2;
}

void MapRenderer::setField(std::shared_ptr<const CurrentField> field, double time, double depth)
{
    field_ = std::move(field);
    fieldTime_ = time;
    fieldDepth_ = depth;
}

void MapRenderer::addPolygon(MapPolygon polygon)
{
    if (polygon.vertices.size() < 3)
        throw Error("MapRenderer::addPolygon: polygon '" + polygon.label + "' needs at least 3 vertices (got " +
                    std::to_string(polygon.vertices.size()) + ")");
    for (const auto &v : polygon.vertices)
        if (!std::isfinite(v.x) || !std::isfinite(v.y))
            throw Error("MapRenderer::addPolygon: polygon '" + polygon.label + "' has a non-finite vertex");
    polygons_.push_back(std::move(polygon));
}

void MapRenderer::addPath(MapPath path)
{
    if (!path.waypoints.empty())
        paths_.push_back(std::move(path));
}

void MapRenderer::addStation(Point2 at, double radius, std::string label)
{
    stations_.push_back({at, std::isfinite(radius) ? radius : 0.0, std::move(label)});
}

void MapRenderer::setStartGoal(double sx, double sy, double gx, double gy)
{
    hasStartGoal_ = true;
    sx_ = sx;
    sy_ = sy;
    gx_ = gx;
    gy_ = gy;
}

void MapRenderer::addNote(std::string note)
{
    notes_.push_back(std::move(note));
}

void MapRenderer::addVectors(MapVectors vectors)
{
    if (vectors.at.size() != vectors.velocity.size())
        throw Error("MapRenderer::addVectors: " + std::to_string(vectors.at.size()) + " tails and " +
                    std::to_string(vectors.velocity.size()) + " velocities");
    if (!vectors.at.empty())
        vectors_.push_back(std::move(vectors));
}

void MapRenderer::setGridFill(MapGridFill fill)
{
    if (fill.nx < 1 || fill.ny < 1 || fill.values.size() != static_cast<std::size_t>(fill.nx) * fill.ny ||
        !(fill.h > 0.0) || !std::isfinite(fill.h))
        throw Error("MapRenderer::setGridFill: expected nx * ny values on a spacing > 0");
    fill_ = std::move(fill);
}

Rgba fillColour(double p)
{
    p = std::clamp(p, 0.0, 1.0);
    // light yellow, orange, dark red; the more likely, the less see-through
    return {1.0 - 0.35 * p, 0.92 - 0.80 * p, 0.45 - 0.40 * p, 0.25 + 0.45 * p};
}

std::pair<int, int> MapRenderer::size() const
{
    const double plotW = options_.width - kLeft - kRight;
    const double scale = plotW / (region_.xMax - region_.xMin);
    const double plotH = scale * (region_.yMax - region_.yMin);
    const int h = static_cast<int>(std::ceil(std::max(kTop + plotH + kBottom, 560.0)));
    // the page is as tall as the legend needs (measured on a recording surface), so that nothing of it is cut
    cairo_surface_t *probe = cairo_recording_surface_create(CAIRO_CONTENT_COLOR_ALPHA, nullptr);
    cairo_t *cr = cairo_create(probe);
    const double legend = map_detail::MapPainter(*this, cr, h).legendBottom();
    cairo_destroy(cr);
    cairo_surface_destroy(probe);
    return {options_.width, std::max(h, static_cast<int>(std::ceil(legend + 12.0)))};
}

MapPath MapRenderer::rawPathStyle(std::string label, std::vector<TimedPoint> waypoints)
{
    return styledPath(std::move(label), std::move(waypoints), {0.35, 0.35, 0.35, 0.9}, 1.4, /*dashed=*/true,
                      /*waypointMarkers=*/true, /*timeTicks=*/false);
}

MapPath MapRenderer::stintTrackStyle(std::string label, std::vector<TimedPoint> track, int index)
{
    static const Rgba palette[] = {{0.85, 0.10, 0.10, 1.0}, {0.10, 0.45, 0.95, 1.0}, {0.95, 0.55, 0.05, 1.0},
                                   {0.45, 0.20, 0.70, 1.0}, {0.10, 0.60, 0.25, 1.0}, {0.35, 0.35, 0.35, 1.0}};
    return styledPath(std::move(label), std::move(track), palette[((index % 6) + 6) % 6], 2.0, /*dashed=*/false,
                      /*waypointMarkers=*/false, /*timeTicks=*/false);
}

MapPath MapRenderer::smoothedPathStyle(std::string label, std::vector<TimedPoint> waypoints)
{
    return styledPath(std::move(label), std::move(waypoints), {0.95, 0.55, 0.0, 1.0}, 2.2, /*dashed=*/false,
                      /*waypointMarkers=*/true, /*timeTicks=*/false);
}

MapPath MapRenderer::refinedPathStyle(std::string label, std::vector<TimedPoint> waypoints)
{
    return styledPath(std::move(label), std::move(waypoints), {0.85, 0.05, 0.10, 1.0}, 3.0, /*dashed=*/false,
                      /*waypointMarkers=*/true, /*timeTicks=*/true);
}

void MapRenderer::draw(void *cairoContext) const
{
    map_detail::MapPainter(*this, static_cast<cairo_t *>(cairoContext)).paint();
}

void MapRenderer::writeSvg(const std::string &filename) const
{
    const auto [W, H] = size();
    writeCairoFile(filename, W, H, true, [this](void *cr) { draw(cr); });
}

void MapRenderer::writePng(const std::string &filename) const
{
    const auto [W, H] = size();
    writeCairoFile(filename, W, H, false, [this](void *cr) { draw(cr); });
}
} // namespace ompl_glider
