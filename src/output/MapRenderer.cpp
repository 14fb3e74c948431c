#include "ompl_glider/output/MapRenderer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <set>
#include <tuple>

#include <cairo-svg.h>
#include <cairo.h>

#include "ompl_glider/Exception.h"
#include "ompl_glider/current/GeoBox.h"
#include "ompl_glider/current/GriddedCurrentField.h"

namespace ompl_glider
{
namespace
{
constexpr double kLeft = 72, kRight = 270, kTop = 52, kBottom = 58;
constexpr double kPi = 3.14159265358979323846;
/// Speed-shading values of the points without a current: land of the field (closed cells of a gridded forecast,
/// or wherever an analytic field has no water) and no data (outside a gridded forecast's grid).
constexpr double kLand = -1.0, kNoData = -2.0;
const Rgba kLandColour{0.80, 0.76, 0.68, 1.0}, kNoDataColour{0.90, 0.90, 0.92, 1.0};

double niceStep(double raw)
{
    if (!(raw > 0.0) || !std::isfinite(raw))
        return 1.0;
    const double p = std::pow(10.0, std::floor(std::log10(raw)));
    const double m = raw / p;
    return p * (m <= 1.0 ? 1.0 : m <= 2.0 ? 2.0 : m <= 5.0 ? 5.0 : 10.0);
}

std::string fmt(double v, int prec = -1)
{
    char buf[64];
    if (prec < 0)
    {
        const double a = std::abs(v);
        prec = a == 0.0 || a >= 100 ? 0 : a >= 10 ? 1 : a >= 1 ? 2 : 3;
        // Drop trailing decimals of round values.
        if (std::abs(v - std::round(v)) < 1e-9 * std::max(1.0, a))
            prec = 0;
    }
    std::snprintf(buf, sizeof buf, "%.*f", prec, v);
    return buf;
}

/// A graticule step in degrees giving about `lines` lines over `span` degrees.
double degreeStep(double span, double lines)
{
    for (double s : {0.01, 0.02, 0.05, 0.1, 0.2, 0.25, 0.5, 1.0, 2.0, 5.0, 10.0, 15.0, 30.0})
        if (span / s <= lines)
            return s;
    return 45.0;
}

/// "76.50°W", "18.2°N": a longitude (east) or latitude (north) with as many decimals as the step needs.
std::string degrees(double v, double step, bool east)
{
    int d = 0;
    while (d < 3 && std::abs(step * std::pow(10.0, d) - std::round(step * std::pow(10.0, d))) > 1e-6)
        ++d;
    if (east)
        v = std::remainder(v, 360.0);
    if (std::abs(v) < 1e-9)
        v = 0.0;
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.*f\u00b0%s", d, std::abs(v),
                  v == 0.0 || (!east && std::abs(v) < 1e-9) ? "" : east ? (v < 0 ? "W" : "E") : (v < 0 ? "S" : "N"));
    return buf;
}

void setColour(cairo_t *cr, const Rgba &c)
{
    cairo_set_source_rgba(cr, c.r, c.g, c.b, c.a);
}


/// Text with a white halo so that it stays readable over lines and shading.
void haloText(cairo_t *cr, double x, double y, const std::string &s, const Rgba &c, double size, bool bold = false,
              double alignX = 0.0)
{
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL,
                           bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, size);
    cairo_text_extents_t ext;
    cairo_text_extents(cr, s.c_str(), &ext);
    const double x0 = x - alignX * ext.x_advance;
    cairo_move_to(cr, x0, y);
    cairo_text_path(cr, s.c_str());
    cairo_set_source_rgba(cr, 1, 1, 1, 0.85);
    cairo_set_line_width(cr, 3.0);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    cairo_stroke(cr);
    cairo_move_to(cr, x0, y);
    setColour(cr, c);
    cairo_show_text(cr, s.c_str());
    cairo_new_path(cr);  // show_text leaves a current point: do not let the next arc connect to it
}

void plainText(cairo_t *cr, double x, double y, const std::string &s, double size, bool bold = false,
               double alignX = 0.0, Rgba c = {0.1, 0.1, 0.1, 1.0})
{
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL,
                           bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, size);
    cairo_text_extents_t ext;
    cairo_text_extents(cr, s.c_str(), &ext);
    cairo_move_to(cr, x - alignX * ext.x_advance, y);
    setColour(cr, c);
    cairo_show_text(cr, s.c_str());
    cairo_new_path(cr);  // show_text leaves a current point: do not let the next arc connect to it
}

/// Draws @p s left-aligned at (x, y), broken at spaces (or, for a single long word, at any character) so that no
/// line is wider than @p maxWidth; returns the number of lines drawn.
int wrappedText(cairo_t *cr, double x, double y, const std::string &s, double size, double maxWidth,
                double lineHeight, Rgba c = {0.1, 0.1, 0.1, 1.0})
{
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, size);
    auto width = [cr](const std::string &t) {
        cairo_text_extents_t ext;
        cairo_text_extents(cr, t.c_str(), &ext);
        return ext.x_advance;
    };
    std::vector<std::string> lines;
    std::string rest = s;
    while (!rest.empty())
    {
        if (width(rest) <= maxWidth)
        {
            lines.push_back(rest);
            break;
        }
        // longest prefix that fits, preferring to break after a space
        std::size_t fit = 1;
        while (fit < rest.size() && width(rest.substr(0, fit + 1)) <= maxWidth)
            ++fit;
        const std::size_t space = rest.rfind(' ', fit);
        const std::size_t cut = (space != std::string::npos && space > 0) ? space : fit;
        lines.push_back(rest.substr(0, cut));
        rest = rest.substr(cut);
        while (!rest.empty() && rest.front() == ' ')
            rest.erase(0, 1);
    }
    for (std::size_t i = 0; i < lines.size(); ++i)
        plainText(cr, x, y + i * lineHeight, lines[i], size, false, 0.0, c);
    return static_cast<int>(lines.size());
}

Rgba speedColour(double f)
{
    f = std::clamp(f, 0.0, 1.0);
    // very light blue -> medium blue
    const Rgba lo{0.97, 0.98, 1.00, 1.0}, hi{0.42, 0.62, 0.88, 1.0};
    return {lo.r + f * (hi.r - lo.r), lo.g + f * (hi.g - lo.g), lo.b + f * (hi.b - lo.b), 1.0};
}

void arrow(cairo_t *cr, double x, double y, double dx, double dy, double head)
{
    const double len = std::hypot(dx, dy);
    if (len < 1e-9)
        return;
    const double ux = dx / len, uy = dy / len;
    const double x2 = x + dx, y2 = y + dy;
    cairo_move_to(cr, x, y);
    cairo_line_to(cr, x2 - ux * head * 0.6, y2 - uy * head * 0.6);
    cairo_stroke(cr);
    cairo_move_to(cr, x2, y2);
    cairo_line_to(cr, x2 - ux * head - uy * head * 0.45, y2 - uy * head + ux * head * 0.45);
    cairo_line_to(cr, x2 - ux * head + uy * head * 0.45, y2 - uy * head - ux * head * 0.45);
    cairo_close_path(cr);
    cairo_fill(cr);
}
/// Meridians and parallels through the field's frame (toLocal of points along each) when `lines`; else their
/// labels where they leave the plot at the bottom (longitudes) and left (latitudes) edges, and a scale bar when the
/// frame is in metres.
void drawGraticule(cairo_t *cr, const Region &reg, const MapOptions &o, const std::function<double(double)> &X,
                   const std::function<double(double)> &Y, bool lines)
{
    // the lon/lat extent of the plot
    const GeoBox gb = frameBounds(reg, o.toGeographic);
    const double lon0 = gb.lonMin, lon1 = gb.lonMax, lat0 = gb.latMin, lat1 = gb.latMax;
    if (!(lon1 > lon0) || !(lat1 > lat0))
        return;
    const double step = degreeStep(std::max(lon1 - lon0, lat1 - lat0), 7.0);
    const int n = 80;
    auto line = [&](bool meridian, double v) {
        std::vector<Point2> pts;
        for (int k = 0; k <= n; ++k)
        {
            const double s = k / double(n);
            const LonLat g = meridian ? LonLat{v, lat0 + s * (lat1 - lat0)} : LonLat{lon0 + s * (lon1 - lon0), v};
            pts.push_back(o.toLocal(g));
        }
        return pts;
    };
    if (lines)
    {
    cairo_save(cr);
    cairo_rectangle(cr, X(reg.xMin), Y(reg.yMax), X(reg.xMax) - X(reg.xMin), Y(reg.yMin) - Y(reg.yMax));
    cairo_clip(cr);
    cairo_set_source_rgba(cr, 0.25, 0.25, 0.25, 0.45);
    cairo_set_line_width(cr, 0.7);
    for (int meridian = 0; meridian < 2; ++meridian)
        for (double v = std::ceil((meridian ? lon0 : lat0) / step) * step; v <= (meridian ? lon1 : lat1) + 1e-9;
             v += step)
        {
            const auto pts = line(meridian, v);
            for (std::size_t k = 0; k < pts.size(); ++k)
                k == 0 ? cairo_move_to(cr, X(pts[k].x), Y(pts[k].y)) : cairo_line_to(cr, X(pts[k].x), Y(pts[k].y));
            cairo_stroke(cr);
        }
    cairo_restore(cr);
    return;
    }
    // labels where the lines leave the plot: meridians at the bottom edge, parallels at the left edge
    for (int meridian = 0; meridian < 2; ++meridian)
        for (double v = std::ceil((meridian ? lon0 : lat0) / step) * step; v <= (meridian ? lon1 : lat1) + 1e-9;
             v += step)
        {
            const auto pts = line(meridian, v);
            for (std::size_t k = 0; k + 1 < pts.size(); ++k)
            {
                const Point2 a = pts[k], b = pts[k + 1];
                if (meridian && (a.y - reg.yMin) * (b.y - reg.yMin) <= 0 && a.y != b.y)
                {
                    const double x = a.x + (reg.yMin - a.y) / (b.y - a.y) * (b.x - a.x);
                    if (x < reg.xMin || x > reg.xMax)
                        continue;
                    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
                    cairo_move_to(cr, X(x), Y(reg.yMin));
                    cairo_line_to(cr, X(x), Y(reg.yMin) + 5);
                    cairo_stroke(cr);
                    plainText(cr, X(x), Y(reg.yMin) + 19, degrees(v, step, true), 12, false, 0.5);
                    break;
                }
                if (!meridian && (a.x - reg.xMin) * (b.x - reg.xMin) <= 0 && a.x != b.x)
                {
                    const double y = a.y + (reg.xMin - a.x) / (b.x - a.x) * (b.y - a.y);
                    if (y < reg.yMin || y > reg.yMax)
                        continue;
                    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
                    cairo_move_to(cr, X(reg.xMin) - 5, Y(y));
                    cairo_line_to(cr, X(reg.xMin), Y(y));
                    cairo_stroke(cr);
                    plainText(cr, X(reg.xMin) - 8, Y(y) + 4, degrees(v, step, false), 12, false, 1.0);
                    break;
                }
            }
        }
    // scale bar: a round number of km about a fifth of the width, bottom left inside the plot
    if (o.metresPerUnit > 0.0)
    {
        const double widthKm = (reg.xMax - reg.xMin) * o.metresPerUnit / 1000.0;
        const double raw = widthKm / 5.0, p = std::pow(10.0, std::floor(std::log10(raw))), m = raw / p;
        const double km = p * (m < 2.0 ? 1.0 : m < 5.0 ? 2.0 : 5.0);
        const double len = km * 1000.0 / o.metresPerUnit;
        const double x0 = X(reg.xMin) + 16, y0 = Y(reg.yMin) - 16, x1 = x0 + (X(reg.xMin + len) - X(reg.xMin));
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
}

}  // namespace

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

std::pair<int, int> MapRenderer::size() const
{
    const double plotW = options_.width - kLeft - kRight;
    const double scale = plotW / (region_.xMax - region_.xMin);
    const double plotH = scale * (region_.yMax - region_.yMin);
    const int h = static_cast<int>(std::ceil(std::max(kTop + plotH + kBottom, 560.0)));
    return {options_.width, h};
}

MapPath MapRenderer::rawPathStyle(std::string label, std::vector<TimedPoint> waypoints)
{
    MapPath p;
    p.label = std::move(label);
    p.waypoints = std::move(waypoints);
    p.colour = {0.35, 0.35, 0.35, 0.9};
    p.width = 1.4;
    p.dashed = true;
    p.waypointMarkers = true;
    return p;
}

MapPath MapRenderer::stintTrackStyle(std::string label, std::vector<TimedPoint> track, int index)
{
    static const Rgba palette[] = {{0.85, 0.10, 0.10, 1.0}, {0.10, 0.45, 0.95, 1.0}, {0.95, 0.55, 0.05, 1.0},
                                   {0.45, 0.20, 0.70, 1.0}, {0.10, 0.60, 0.25, 1.0}, {0.35, 0.35, 0.35, 1.0}};
    MapPath p;
    p.label = std::move(label);
    p.waypoints = std::move(track);
    p.colour = palette[((index % 6) + 6) % 6];
    p.width = 2.0;
    p.dashed = false;
    p.waypointMarkers = false;
    return p;
}

MapPath MapRenderer::smoothedPathStyle(std::string label, std::vector<TimedPoint> waypoints)
{
    MapPath p;
    p.label = std::move(label);
    p.waypoints = std::move(waypoints);
    p.colour = {0.95, 0.55, 0.0, 1.0};
    p.width = 2.2;
    p.waypointMarkers = true;
    return p;
}

MapPath MapRenderer::refinedPathStyle(std::string label, std::vector<TimedPoint> waypoints)
{
    MapPath p;
    p.label = std::move(label);
    p.waypoints = std::move(waypoints);
    p.colour = {0.85, 0.05, 0.10, 1.0};
    p.width = 3.0;
    p.waypointMarkers = true;
    p.timeTicks = true;
    return p;
}

void MapRenderer::draw(void *context) const
{
    auto *cr = static_cast<cairo_t *>(context);
    const auto [W, H] = size();
    const double plotW = W - kLeft - kRight;
    const double scale = plotW / (region_.xMax - region_.xMin);
    const double plotH = scale * (region_.yMax - region_.yMin);
    auto X = [&](double x) { return kLeft + (x - region_.xMin) * scale; };
    auto Y = [&](double y) { return kTop + (region_.yMax - y) * scale; };
    const std::string tu = options_.timeUnit.empty() ? "" : " " + options_.timeUnit;
    // a position for the legend: degrees in a geographic frame, else the frame's x/y
    auto position = [&](double x, double y) {
        if (!(options_.toGeographic && options_.toLocal))
            return "(" + fmt(x) + ", " + fmt(y) + ")";
        const LonLat g = options_.toGeographic({x, y});
        return degrees(g.lat, 0.001, false) + " " + degrees(g.lon, 0.001, true);
    };

    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);

    // --- field: speed shading and arrows, clipped to the plot area
    cairo_save(cr);
    cairo_rectangle(cr, kLeft, kTop, plotW, plotH);
    cairo_clip(cr);
    double vmax = 0.0;
    bool landShown = false, noDataShown = false;
    if (field_)
    {
        const int cell = 6;
        const int nx = static_cast<int>(std::ceil(plotW / cell)), ny = static_cast<int>(std::ceil(plotH / cell));
        std::vector<double> sp(static_cast<std::size_t>(nx) * ny, 0.0);
        // a gridded forecast tells land (closed nodes of its grid) from no data (outside its grid)
        const auto *grid = dynamic_cast<const GriddedCurrentField *>(field_.get());
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i)
            {
                const double x = region_.xMin + (i + 0.5) * cell / scale, y = region_.yMax - (j + 0.5) * cell / scale;
                double s = 0.0;
                if (field_->inWater(x, y, fieldDepth_))
                {
                    const Velocity c = field_->velocity(x, y, fieldDepth_, fieldTime_);
                    s = std::hypot(c.u, c.v);
                    if (!std::isfinite(s))
                        s = 0.0;
                }
                else
                {
                    double fi, fj;
                    s = grid && !grid->locate(x, y, fi, fj) ? kNoData : kLand;
                    (s == kLand ? landShown : noDataShown) = true;
                }
                sp[static_cast<std::size_t>(j) * nx + i] = s;
                vmax = std::max(vmax, s);
            }
        if (options_.speedShading)
            for (int j = 0; j < ny; ++j)
                for (int i = 0; i < nx; ++i)
                {
                    const double s = sp[static_cast<std::size_t>(j) * nx + i];
                    setColour(cr, s == kLand     ? kLandColour
                                  : s == kNoData ? kNoDataColour
                                                 : speedColour(vmax > 0 ? s / vmax : 0.0));
                    cairo_rectangle(cr, kLeft + i * cell, kTop + j * cell, cell + 0.5, cell + 0.5);
                    cairo_fill(cr);
                }
        const int cols = options_.arrows ? options_.arrowColumns : 0;
        const double dxCell = (region_.xMax - region_.xMin) / cols;
        const int rows =
            cols == 0 ? 0 : std::max(2, static_cast<int>(std::round((region_.yMax - region_.yMin) / dxCell)));
        const double dyCell = (region_.yMax - region_.yMin) / rows;
        const double cellPx = std::min(dxCell, dyCell) * scale;
        cairo_set_source_rgba(cr, 0.10, 0.20, 0.40, 0.75);
        cairo_set_line_width(cr, 1.1);
        for (int j = 0; j < rows; ++j)
            for (int i = 0; i < cols; ++i)
            {
                const double x = region_.xMin + (i + 0.5) * dxCell, y = region_.yMin + (j + 0.5) * dyCell;
                if (!field_->inWater(x, y, fieldDepth_))
                    continue;
                const Velocity c = field_->velocity(x, y, fieldDepth_, fieldTime_);
                const double s = std::hypot(c.u, c.v);
                if (!(s > 0.0) || !std::isfinite(s) || !(vmax > 0))
                    continue;
                const double len = 0.9 * cellPx * s / vmax;
                if (len < 2.0)
                    continue;
                const double cx = X(x) - 0.5 * len * c.u / s, cy = Y(y) + 0.5 * len * c.v / s;
                arrow(cr, cx, cy, len * c.u / s, -len * c.v / s, std::min(6.0, 0.35 * len + 2.0));
            }
    }
    // light grid
    const double xs = niceStep((region_.xMax - region_.xMin) / 8), ys = niceStep((region_.yMax - region_.yMin) / 8);
    cairo_set_source_rgba(cr, 0.3, 0.3, 0.3, 0.18);
    cairo_set_line_width(cr, 0.8);
    const bool geographic = options_.toGeographic && options_.toLocal;
    if (geographic)
        drawGraticule(cr, region_, options_, X, Y, true);
    for (double x = std::ceil(region_.xMin / xs) * xs; !geographic && x <= region_.xMax + 1e-9; x += xs)
    {
        cairo_move_to(cr, X(x), kTop);
        cairo_line_to(cr, X(x), kTop + plotH);
    }
    for (double y = std::ceil(region_.yMin / ys) * ys; !geographic && y <= region_.yMax + 1e-9; y += ys)
    {
        cairo_move_to(cr, kLeft, Y(y));
        cairo_line_to(cr, kLeft + plotW, Y(y));
    }
    cairo_stroke(cr);

    // --- forbidden regions
    for (const MapPolygon &poly : polygons_)
    {
        cairo_new_path(cr);
        for (std::size_t k = 0; k < poly.vertices.size(); ++k)
        {
            const double px = X(poly.vertices[k].x), py = Y(poly.vertices[k].y);
            k == 0 ? cairo_move_to(cr, px, py) : cairo_line_to(cr, px, py);
        }
        cairo_close_path(cr);
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
            // restore the polygon outline path for the stroke below
            cairo_new_path(cr);
            for (std::size_t k = 0; k < poly.vertices.size(); ++k)
            {
                const double px = X(poly.vertices[k].x), py = Y(poly.vertices[k].y);
                k == 0 ? cairo_move_to(cr, px, py) : cairo_line_to(cr, px, py);
            }
            cairo_close_path(cr);
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
            haloText(cr, X(cx), Y(cy) + 4, poly.label, poly.stroke, 12, true, 0.5);
        }
    }

    // --- paths
    for (const MapPath &p : paths_)
    {
        cairo_new_path(cr);
        for (std::size_t k = 0; k < p.waypoints.size(); ++k)
        {
            const double px = X(p.waypoints[k].x), py = Y(p.waypoints[k].y);
            k == 0 ? cairo_move_to(cr, px, py) : cairo_line_to(cr, px, py);
        }
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
        if (p.dashed)
        {
            const double dash[] = {6.0, 4.0};
            cairo_set_dash(cr, dash, 2, 0);
        }
        cairo_stroke(cr);
        cairo_set_dash(cr, nullptr, 0, 0);
        if (p.waypointMarkers)
            for (const TimedPoint &w : p.waypoints)
            {
                cairo_new_path(cr);
                cairo_arc(cr, X(w.x), Y(w.y), p.width + 1.2, 0, 2 * kPi);
                cairo_set_source_rgb(cr, 1, 1, 1);
                cairo_fill_preserve(cr);
                setColour(cr, p.colour);
                cairo_set_line_width(cr, 1.3);
                cairo_stroke(cr);
            }
        if (p.timeTicks && p.waypoints.size() >= 2 && std::isfinite(p.waypoints.back().t))
        {
            const double tA = p.waypoints.front().t, tB = p.waypoints.back().t;
            const double step = options_.tickInterval > 0 ? options_.tickInterval : niceStep((tB - tA) / 10);
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
                haloText(cr, x + side * 16 * nx, y + side * 16 * ny + 4, "t=" + fmt(T) + tu, {0.1, 0.1, 0.1, 1}, 11,
                         false, 0.5);
            }
        }
    }

    // --- start and goal
    if (hasStartGoal_)
    {
        cairo_new_path(cr);
        cairo_arc(cr, X(sx_), Y(sy_), 8, 0, 2 * kPi);
        cairo_set_source_rgb(cr, 0.05, 0.60, 0.15);
        cairo_fill_preserve(cr);
        cairo_set_source_rgb(cr, 1, 1, 1);
        cairo_set_line_width(cr, 2);
        cairo_stroke(cr);
        haloText(cr, X(sx_) + 11, Y(sy_) - 9, "START", {0.05, 0.45, 0.1, 1}, 13, true);
        const double gxp = X(gx_), gyp = Y(gy_);
        cairo_new_path(cr);
        for (int k = 0; k < 10; ++k)
        {
            const double r = k % 2 ? 4.5 : 11.0, a = -kPi / 2 + k * kPi / 5;
            k == 0 ? cairo_move_to(cr, gxp + r * std::cos(a), gyp + r * std::sin(a))
                   : cairo_line_to(cr, gxp + r * std::cos(a), gyp + r * std::sin(a));
        }
        cairo_close_path(cr);
        cairo_set_source_rgb(cr, 0.55, 0.0, 0.55);
        cairo_fill_preserve(cr);
        cairo_set_source_rgb(cr, 1, 1, 1);
        cairo_set_line_width(cr, 1.5);
        cairo_stroke(cr);
        haloText(cr, gxp + 12, gyp - 10, "GOAL", {0.45, 0.0, 0.45, 1}, 13, true);
    }
    cairo_restore(cr);

    // --- frame, axes, ticks
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    cairo_set_line_width(cr, 1.2);
    cairo_rectangle(cr, kLeft, kTop, plotW, plotH);
    cairo_stroke(cr);
    if (geographic)
        drawGraticule(cr, region_, options_, X, Y, false);
    for (double x = std::ceil(region_.xMin / xs) * xs; !geographic && x <= region_.xMax + 1e-9; x += xs)
    {
        cairo_move_to(cr, X(x), kTop + plotH);
        cairo_line_to(cr, X(x), kTop + plotH + 5);
        cairo_stroke(cr);
        plainText(cr, X(x), kTop + plotH + 19, fmt(std::abs(x) < 1e-12 ? 0.0 : x), 12, false, 0.5);
    }
    for (double y = std::ceil(region_.yMin / ys) * ys; !geographic && y <= region_.yMax + 1e-9; y += ys)
    {
        cairo_move_to(cr, kLeft - 5, Y(y));
        cairo_line_to(cr, kLeft, Y(y));
        cairo_stroke(cr);
        plainText(cr, kLeft - 8, Y(y) + 4, fmt(std::abs(y) < 1e-12 ? 0.0 : y), 12, false, 1.0);
    }
    plainText(cr, kLeft + plotW / 2, kTop + plotH + 42, geographic ? "longitude" : "x (east)", 13, true, 0.5);
    cairo_save(cr);
    cairo_move_to(cr, 0, 0);
    cairo_translate(cr, 22, kTop + plotH / 2);
    cairo_rotate(cr, -kPi / 2);
    plainText(cr, 0, 0, geographic ? "latitude" : "y (north)", 13, true, 0.5);
    cairo_restore(cr);
    if (!options_.title.empty())
        plainText(cr, kLeft, 32, options_.title, 17, true);

    // --- legend
    double lx = kLeft + plotW + 22, ly = kTop + 8;
    plainText(cr, lx, ly + 6, "Legend", 14, true);
    ly += 26;
    for (const MapPath &p : paths_)
    {
        if (p.label.empty())  // a line without a legend entry (e.g. the further pieces of one isochrone)
            continue;
        setColour(cr, p.colour);
        cairo_set_line_width(cr, p.width);
        if (p.dashed)
        {
            const double dash[] = {6.0, 4.0};
            cairo_set_dash(cr, dash, 2, 0);
        }
        cairo_move_to(cr, lx, ly);
        cairo_line_to(cr, lx + 30, ly);
        cairo_stroke(cr);
        cairo_set_dash(cr, nullptr, 0, 0);
        if (p.waypointMarkers)
        {
            cairo_new_path(cr);
            cairo_arc(cr, lx + 15, ly, p.width + 1.2, 0, 2 * kPi);
            cairo_set_source_rgb(cr, 1, 1, 1);
            cairo_fill_preserve(cr);
            setColour(cr, p.colour);
            cairo_set_line_width(cr, 1.3);
            cairo_stroke(cr);
        }
        plainText(cr, lx + 38, ly + 4, p.label, 11.5);
        ly += 22;
    }
    if (hasStartGoal_)
    {
        cairo_new_path(cr);
        cairo_arc(cr, lx + 15, ly, 6, 0, 2 * kPi);
        cairo_set_source_rgb(cr, 0.05, 0.60, 0.15);
        cairo_fill(cr);
        plainText(cr, lx + 38, ly + 4, "start " + position(sx_, sy_), 12);
        ly += 22;
        cairo_new_path(cr);
        for (int k = 0; k < 10; ++k)
        {
            const double r = k % 2 ? 3.5 : 8.0, a = -kPi / 2 + k * kPi / 5;
            k == 0 ? cairo_move_to(cr, lx + 15 + r * std::cos(a), ly + r * std::sin(a))
                   : cairo_line_to(cr, lx + 15 + r * std::cos(a), ly + r * std::sin(a));
        }
        cairo_close_path(cr);
        cairo_set_source_rgb(cr, 0.55, 0.0, 0.55);
        cairo_fill(cr);
        plainText(cr, lx + 38, ly + 4, "goal " + position(gx_, gy_), 12);
        ly += 22;
    }
    // the field's land and no-data areas (when the map shades them)
    for (const auto &[shown, colour, label] :
         {std::tuple<bool, Rgba, const char *>{landShown, kLandColour, "land (closed grid cells)"},
          {noDataShown, kNoDataColour, "no data (outside the forecast)"}})
    {
        if (!shown || !options_.speedShading)
            continue;
        cairo_rectangle(cr, lx + 5, ly - 7, 20, 14);
        setColour(cr, colour);
        cairo_fill_preserve(cr);
        cairo_set_source_rgb(cr, 0.4, 0.4, 0.4);
        cairo_set_line_width(cr, 0.8);
        cairo_stroke(cr);
        plainText(cr, lx + 38, ly + 4, label, 12);
        ly += 22;
    }
    std::set<std::string> seen;
    for (const MapPolygon &poly : polygons_)
    {
        if (!seen.insert(poly.label).second)
            continue;
        cairo_rectangle(cr, lx + 5, ly - 7, 20, 14);
        setColour(cr, poly.fill);
        cairo_fill_preserve(cr);
        setColour(cr, poly.stroke);
        cairo_set_line_width(cr, 1.2);
        cairo_stroke(cr);
        plainText(cr, lx + 38, ly + 4, poly.label.empty() ? "forbidden region" : poly.label, 12);
        ly += 22;
    }
    if (field_)
    {
        if (options_.arrows)
        {
            cairo_set_source_rgba(cr, 0.10, 0.20, 0.40, 0.9);
            cairo_set_line_width(cr, 1.1);
            arrow(cr, lx + 2, ly, 26, 0, 6);
            plainText(cr, lx + 38, ly + 4, "current at t=" + fmt(fieldTime_) + tu, 12);
            ly += 20;
            ly += 16 * wrappedText(cr, lx + 38, ly + 4, "(" + field_->name() + ")", 11, W - lx - 46, 16,
                                   {0.3, 0.3, 0.3, 1}) + 6;
        }
        if (options_.speedShading && vmax > 0)
        {
            const std::string label = !options_.shadingLabel.empty() ? options_.shadingLabel
                                      : options_.speedInMetresPerSecond ? "current speed (m/s)"
                                                                        : "current speed";
            plainText(cr, lx, ly + 4, label, 12);
            ly += 12;
            const double bw = 150, bh = 12;
            for (int k = 0; k < 60; ++k)
            {
                setColour(cr, speedColour(k / 59.0));
                cairo_rectangle(cr, lx + k * bw / 60, ly, bw / 60 + 0.5, bh);
                cairo_fill(cr);
            }
            cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
            cairo_set_line_width(cr, 0.8);
            cairo_rectangle(cr, lx, ly, bw, bh);
            cairo_stroke(cr);
            plainText(cr, lx, ly + bh + 13, "0", 11, false, 0.5);
            plainText(cr, lx + bw, ly + bh + 13,
                      fmt(vmax) + (options_.speedInMetresPerSecond ? " (" + fmt(vmax * 3600.0 / 1852.0) + " kn)" : ""),
                      11, false, 0.5);
            ly += bh + 30;
        }
    }
    bool tickNote = false;
    for (const MapPath &p : paths_)
        tickNote = tickNote || p.timeTicks;
    if (tickNote)
    {
        plainText(cr, lx, ly + 4, "ticks: time along the path", 11, false, 0.0, {0.3, 0.3, 0.3, 1});
        ly += 20;
    }
    ly += 6;
    for (const std::string &n : notes_)
        ly += 18 * wrappedText(cr, lx, ly + 4, n, 12, W - lx - 8, 18);
}

void drawCairoText(void *cairo, double x, double y, const std::string &text, double size, bool bold, double alignX,
                   Rgba colour)
{
    plainText(static_cast<cairo_t *>(cairo), x, y, text, size, bold, alignX, colour);
}

double niceAxisStep(double raw)
{
    return niceStep(raw);
}

void writeCairoFile(const std::string &filename, int width, int height, bool svg,
                    const std::function<void(void *)> &draw)
{
    cairo_surface_t *surf = svg ? cairo_svg_surface_create(filename.c_str(), width, height)
                                : cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height);
    if (cairo_surface_status(surf) != CAIRO_STATUS_SUCCESS)
    {
        const std::string msg = cairo_status_to_string(cairo_surface_status(surf));
        cairo_surface_destroy(surf);
        throw Error("cannot create '" + filename + "': " + msg);
    }
    cairo_t *cr = cairo_create(surf);
    draw(cr);
    cairo_destroy(cr);
    cairo_status_t st;
    if (svg)
    {
        cairo_surface_finish(surf);
        st = cairo_surface_status(surf);
    }
    else
    {
        cairo_surface_flush(surf);
        st = cairo_surface_write_to_png(surf, filename.c_str());
    }
    cairo_surface_destroy(surf);
    if (st != CAIRO_STATUS_SUCCESS)
        throw Error("cannot write '" + filename + "': " + cairo_status_to_string(st));
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
}  // namespace ompl_glider
