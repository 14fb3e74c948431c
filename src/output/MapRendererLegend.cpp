/// @file MapRendererLegend.cpp
/// @brief The map's legend in the right margin: paths, start and goal, land / no-data areas and forbidden regions,
/// the current arrow with the field's name, the colour bar, and the notes (MapRenderer's drawing, see
/// src/output/MapPainter.h).

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
    if (map.hasStartGoal_)
        drawStartGoalEntries();
    if (map.field_)
        drawFieldEntries();
    drawAreaEntries();
    drawNotes();
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
        plainText(cr, lx_ + 38, ly_ + 4, p.label, 11.5);
        ly_ += 22;
    }
}

void MapPainter::drawStartGoalEntries()
{
    cairo_new_path(cr);
    cairo_arc(cr, lx_ + 15, ly_, 6, 0, 2 * kPi);
    cairo_set_source_rgb(cr, 0.05, 0.60, 0.15);
    cairo_fill(cr);
    plainText(cr, lx_ + 38, ly_ + 4, "start " + position(map.sx_, map.sy_), 12);
    ly_ += 22;
    traceStar(cr, lx_ + 15, ly_, 8.0, 3.5);
    cairo_set_source_rgb(cr, 0.55, 0.0, 0.55);
    cairo_fill(cr);
    plainText(cr, lx_ + 38, ly_ + 4, "goal " + position(map.gx_, map.gy_), 12);
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
        plainText(cr, lx_ + 38, ly_ + 4, "and " + std::to_string(more) + " more regions", 12);
        ly_ += 22;
    }
}

void MapPainter::drawFieldEntries()
{
    if (options.arrows)
    {
        cairo_set_source_rgba(cr, 0.10, 0.20, 0.40, 0.9);
        cairo_set_line_width(cr, 1.1);
        arrow(cr, lx_ + 2, ly_, 26, 0, 6);
        plainText(cr, lx_ + 38, ly_ + 4,
                  options.fieldWord + " at " +
                      (options.timeText ? options.timeText(map.fieldTime_) : "t=" + fmt(map.fieldTime_) + tu),
                  12);
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
    const double bw = 150, bh = 12;
    for (int k = 0; k < 60; ++k)
    {
        setColour(cr, speedColour(k / 59.0));
        cairo_rectangle(cr, lx_ + k * bw / 60, ly_, bw / 60 + 0.5, bh);
        cairo_fill(cr);
    }
    cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
    cairo_set_line_width(cr, 0.8);
    cairo_rectangle(cr, lx_, ly_, bw, bh);
    cairo_stroke(cr);
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
        plainText(cr, lx_, ly_ + 4, "ticks: time along the path", 11, false, 0.0, {0.3, 0.3, 0.3, 1});
        ly_ += 20;
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
    plainText(cr, lx_ + 38, ly_ + 4, label, 12);
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
