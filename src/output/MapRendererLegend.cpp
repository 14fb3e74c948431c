/// @file MapRendererLegend.cpp
/// @brief The map's legend in the right margin: paths, start and goal, land / no-data areas and forbidden regions,
/// the current arrow with the field's name, the colour bar, and the notes (MapRenderer's drawing, see
/// src/output/MapPainter.h).

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <string>
#include <tuple>

#include <cairo.h>

#include "MapPainter.h"

namespace ompl_glider
{
namespace map_detail
{
void MapPainter::drawLegend()
{
    lx_ = kLeft + plotW + 22;
    ly_ = kTop + 8;
    plainText(cr, lx_, ly_ + 6, "Legend", 14, true);
    ly_ += 26;
    drawPathEntries();
    drawVectorEntries();
    if (map.hasStartGoal_)
        drawStartGoalEntries();
    if (map.field_)
        drawFieldEntries();
    if (map.fill_)
        drawFillBar();
    drawAreaEntries();
    drawNotes();
}

double MapPainter::legendBottom()
{
    vmax_ = 1.0; // (the colour bar is drawn when the field has a speed: counted whether or not it has)
    landShown_ = noDataShown_ = map.field_ != nullptr;
    drawLegend();
    return ly_;
}

void MapPainter::drawPathEntries()
{
    for (const MapPath &p : map.paths_)
    {
        if (p.label.empty()) // a line without a legend entry (e.g. the further pieces of one isochrone)
            continue;
        setColour(cr, p.colour);
        cairo_set_line_width(cr, p.width);
        setDash(cr, p.dashed);
        cairo_move_to(cr, lx_, ly_);
        cairo_line_to(cr, lx_ + 30, ly_);
        cairo_stroke(cr);
        cairo_set_dash(cr, nullptr, 0, 0);
        if (p.waypointMarkers)
            waypointMarker(cr, lx_ + 15, ly_, p.width + 1.2, p.colour);
        legendLabel(lx_ + 38, p.label, 11.5, 15);
        ly_ += 22;
    }
}

void MapPainter::legendLabel(double x, const std::string &label, double size, double lineHeight)
{
    ly_ += lineHeight * (wrappedText(cr, x, ly_ + 4, label, size, W - x - 6, lineHeight) - 1);
}

std::string MapPainter::keyArrow(double top)
{
    // the largest round speed (1, 2, 5 x 10^k) not above the top
    const double p = top > 0.0 && std::isfinite(top) ? std::pow(10.0, std::floor(std::log10(top))) : 0.0;
    const double m = p > 0.0 ? top / p * (1.0 + 1e-9) : 0.0;
    const double speed = p * (m >= 5.0 ? 5.0 : m >= 2.0 ? 2.0 : 1.0);
    const double len = arrowScale() * speed;
    if (len > 0.0 && std::isfinite(len))
        arrow(cr, lx_ + 2, ly_, len, 0, std::min(6.0, 0.35 * len + 2.0));
    const bool ms = options.speedInMetresPerSecond;
    char text[64];
    std::snprintf(text, sizeof text, ms ? "%g m/s (%.2f kn)" : "%g", speed, speed * 3600.0 / 1852.0);
    return text;
}

void MapPainter::drawVectorEntries()
{
    double fastest = 0.0;
    for (const MapVectors &v : map.vectors_)
        for (const Velocity &c : v.velocity)
            fastest = std::max(fastest, std::hypot(c.u, c.v));
    for (const MapVectors &v : map.vectors_)
    {
        setColour(cr, v.colour);
        cairo_set_line_width(cr, 1.6);
        const std::string key = keyArrow(fastest);
        legendLabel(lx_ + 38, v.label + ": arrow " + key, 11.5, 15);
        ly_ += 22;
    }
}

void MapPainter::drawBar(const std::function<Rgba(int)> &colourOfStep)
{
    // kBarSteps boxes of the colours, framed
    for (int k = 0; k < kBarSteps; ++k)
    {
        setColour(cr, colourOfStep(k));
        cairo_rectangle(cr, lx_ + k * kBarWidth / kBarSteps, ly_, kBarWidth / kBarSteps + 0.5, kBarHeight);
        cairo_fill(cr);
    }
    cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
    cairo_set_line_width(cr, 0.8);
    cairo_rectangle(cr, lx_, ly_, kBarWidth, kBarHeight);
    cairo_stroke(cr);
}

void MapPainter::drawFillBar()
{
    const MapGridFill &f = *map.fill_;
    legendLabel(lx_, f.label, 12, 16);
    ly_ += 12;
    const double bw = kBarWidth, bh = kBarHeight;
    drawBar([](int k) { return fillColour((k + 0.5) / kBarSteps); });
    plainText(cr, lx_, ly_ + bh + 13, "0", 11, false, 0.5);
    plainText(cr, lx_ + bw / 2, ly_ + bh + 13, "0.5", 11, false, 0.5);
    plainText(cr, lx_ + bw, ly_ + bh + 13, "1", 11, false, 0.5);
    ly_ += bh + 30;
}

void MapPainter::drawStartGoalEntries()
{
    cairo_new_path(cr);
    cairo_arc(cr, lx_ + 15, ly_, 6, 0, 2 * kPi);
    cairo_set_source_rgb(cr, 0.05, 0.60, 0.15);
    cairo_fill(cr);
    legendLabel(lx_ + 38, "start " + position(map.sx_, map.sy_), 12, 16);
    ly_ += 22;
    traceStar(cr, lx_ + 15, ly_, 8.0, 3.5);
    cairo_set_source_rgb(cr, 0.55, 0.0, 0.55);
    cairo_fill(cr);
    legendLabel(lx_ + 38, "goal " + position(map.gx_, map.gy_), 12, 16);
    ly_ += 22;
}

void MapPainter::drawAreaEntries()
{
    // the field's land and no-data areas (when the map shades them)
    for (const auto &[shown, colour, label] :
         {std::tuple<bool, Rgba, const char *>{landShown_, kLandColour, "land (closed grid cells)"},
          {noDataShown_, kNoDataColour, "no data (outside the forecast)"}})
    {
        if (!shown || !options.speedShading)
            continue;
        legendSwatch(colour, {0.4, 0.4, 0.4, 1.0}, 0.8, label);
    }
    // one entry per name, at most kMaxAreaEntries of them, so that a coastline of hundreds of polygons (or many
    // regions) never pushes the notes off the page
    constexpr std::size_t kMaxAreaEntries = 8;
    std::set<std::string> seen;
    std::size_t more = 0;
    for (const MapPolygon &poly : map.polygons_)
    {
        const std::string entry = !poly.legend.empty() ? poly.legend
                                  : poly.label.empty() ? std::string("forbidden region")
                                                       : poly.label;
        if (seen.count(entry))
            continue;
        if (seen.size() >= kMaxAreaEntries)
        {
            ++more;
            seen.insert(entry);
            continue;
        }
        seen.insert(entry);
        legendSwatch(poly.fill, poly.stroke, 1.2, entry);
    }
    if (more > 0)
    {
        legendLabel(lx_ + 38, "and " + std::to_string(more) + " more regions", 12, 16);
        ly_ += 22;
    }
}

void MapPainter::drawFieldEntries()
{
    if (options.arrows)
    {
        cairo_set_source_rgba(cr, 0.10, 0.20, 0.40, 0.9);
        cairo_set_line_width(cr, 1.1);
        const std::string key = vmax_ > 0.0 ? keyArrow(vmax_) : std::string();
        legendLabel(lx_ + 38,
                    options.fieldWord + " at " +
                        (options.timeText ? options.timeText(map.fieldTime_) : "t=" + fmt(map.fieldTime_) + tu) +
                        (key.empty() ? "" : ", arrow " + key),
                    12, 16);
        ly_ += 20;
        ly_ += 16 * wrappedText(cr, lx_ + 38, ly_ + 4, "(" + map.field_->name() + ")", 11, W - lx_ - 46, 16,
                                {0.3, 0.3, 0.3, 1}) +
               6;
    }
    if (options.speedShading && vmax_ > 0)
        drawColourBar();
}

void MapPainter::drawColourBar()
{
    const std::string label = !options.shadingLabel.empty()    ? options.shadingLabel
                              : options.speedInMetresPerSecond ? options.fieldWord + " speed (m/s)"
                                                               : options.fieldWord + " speed";
    plainText(cr, lx_, ly_ + 4, label, 12);
    ly_ += 12;
    const double bw = kBarWidth, bh = kBarHeight;
    drawBar([](int k) { return speedColour(k / (kBarSteps - 1.0)); });
    plainText(cr, lx_, ly_ + bh + 13, "0", 11, false, 0.5);
    plainText(cr, lx_ + bw, ly_ + bh + 13,
              fmt(vmax_) + (options.speedInMetresPerSecond ? " (" + fmt(vmax_ * 3600.0 / 1852.0) + " kn)" : ""), 11,
              false, 0.5);
    ly_ += bh + 30;
}

void MapPainter::drawNotes()
{
    bool tickNote = false;
    for (const MapPath &p : map.paths_)
        tickNote = tickNote || p.timeTicks;
    if (tickNote)
    {
        ly_ += 16 * wrappedText(cr, lx_, ly_ + 4,
                                options.tickNote.empty() ? std::string("ticks: time along the path") : options.tickNote,
                                11, W - lx_ - 6, 16, {0.3, 0.3, 0.3, 1}) +
               4;
    }
    ly_ += 6;
    for (const std::string &n : map.notes_)
        ly_ += 18 * wrappedText(cr, lx_, ly_ + 4, n, 12, W - lx_ - 8, 18);
}

void MapPainter::legendSwatch(const Rgba &fill, const Rgba &stroke, double strokeWidth, const std::string &label)
{
    cairo_rectangle(cr, lx_ + 5, ly_ - 7, 20, 14);
    setColour(cr, fill);
    cairo_fill_preserve(cr);
    setColour(cr, stroke);
    cairo_set_line_width(cr, strokeWidth);
    cairo_stroke(cr);
    legendLabel(lx_ + 38, label, 12, 16);
    ly_ += 22;
}

std::string MapPainter::position(double x, double y) const
{
    if (!geographic)
        return "(" + fmt(x) + ", " + fmt(y) + ")";
    const LonLat g = options.toGeographic({x, y});
    return degrees(g.lat, 0.001, false) + " " + degrees(g.lon, 0.001, true);
}
} // namespace map_detail
} // namespace ompl_glider
