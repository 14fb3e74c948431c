// Box plots of an execution's measures per strategy (the shape of [ThompsonICRA] Fig. 8).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <cairo.h>

#include "../io/NumberText.h"
#include "ompl_glider/output/ExecutionFiles.h"
#include "ompl_glider/output/MapRenderer.h"

namespace ompl_glider
{
namespace
{
constexpr int kPanelW = 520, kPanelH = 420, kMarginL = 70, kMarginT = 60, kMarginB = 70;

void drawText(cairo_t *cr, double x, double y, const std::string &s, double size, double align, bool bold = false)
{
    drawCairoText(cr, x, y, s, size, bold, align, {0.0, 0.0, 0.0, 1.0});
}

/// A strategy's name under its box: one line where it fits @p width (12 px type, about 7.2 px a character), else
/// split at the '_' that balances two lines ("replan_observed": "replan" over "observed"), so that six or seven
/// names side by side do not run into each other.
std::vector<std::string> labelLines(const std::string &name, double width)
{
    const double perChar = 7.2;
    if (static_cast<double>(name.size()) * perChar <= width || name.find('_') == std::string::npos)
        return {name};
    std::size_t best = std::string::npos, longest = name.size();
    for (std::size_t at = name.find('_'); at != std::string::npos; at = name.find('_', at + 1))
        if (std::max(at, name.size() - at - 1) < longest)
        {
            longest = std::max(at, name.size() - at - 1);
            best = at;
        }
    return {name.substr(0, best), name.substr(best + 1)};
}

/// One panel at (x0, y0): a box per strategy of the measure chosen by @p pick, scaled by @p scale.
void panel(cairo_t *cr, double x0, double y0, const ExecutionResult &e, const std::string &title,
           const std::string &axis, double scale, const MeasureSpread StrategySpread::*pick)
{
    const double plotW = kPanelW - kMarginL - 20, plotH = kPanelH - kMarginT - kMarginB;
    const double px = x0 + kMarginL, py = y0 + kMarginT;
    double lo = 0.0, hi = 0.0;
    for (const StrategySpread &s : e.spread)
    {
        const MeasureSpread &m = s.*pick;
        if (m.count == 0)
            continue;
        lo = std::min(lo, m.min * scale);
        hi = std::max(hi, m.max * scale);
    }
    if (!(hi > lo))
        hi = lo + 1.0;
    const double step = niceAxisStep((hi - lo) / 6.0);
    lo = std::floor(lo / step) * step;
    hi = std::ceil(hi / step) * step;
    auto Y = [&](double v) { return py + plotH * (1.0 - (v - lo) / (hi - lo)); };

    cairo_set_source_rgb(cr, 0, 0, 0);
    drawText(cr, x0 + kPanelW / 2.0, y0 + 28, title, 15, 0.5, true);
    cairo_set_line_width(cr, 1.0);
    for (double v = lo; v <= hi + 1e-9 * step; v += step)
    {
        cairo_set_source_rgb(cr, 0.85, 0.85, 0.85);
        cairo_move_to(cr, px, Y(v));
        cairo_line_to(cr, px + plotW, Y(v));
        cairo_stroke(cr);
        cairo_set_source_rgb(cr, 0, 0, 0);
        drawText(cr, px - 6, Y(v) + 4, text::number(std::abs(v) < 1e-12 * step ? 0.0 : v, 6), 11, 1.0);
    }
    cairo_rectangle(cr, px, py, plotW, plotH);
    cairo_stroke(cr);
    cairo_save(cr);
    cairo_translate(cr, x0 + 22, py + plotH / 2.0);
    cairo_rotate(cr, -M_PI / 2.0);
    drawText(cr, 0, 0, axis, 12, 0.5);
    cairo_restore(cr);

    // a colour per strategy (seven: controlStrategies())
    const double colours[7][3] = {{0.20, 0.45, 0.75}, {0.30, 0.65, 0.35}, {0.85, 0.45, 0.15}, {0.60, 0.35, 0.70},
                                  {0.55, 0.40, 0.25}, {0.80, 0.30, 0.50}, {0.35, 0.65, 0.70}};
    const std::size_t n = e.spread.size();
    std::size_t lines = 1; // the counts in one row under the tallest name
    for (const StrategySpread &sp : e.spread)
        lines = std::max(lines, labelLines(sp.strategy, plotW / static_cast<double>(n) - 6.0).size());
    for (std::size_t k = 0; k < n; ++k)
    {
        const MeasureSpread &m = e.spread[k].*pick;
        const double cx = px + plotW * (static_cast<double>(k) + 0.5) / static_cast<double>(n);
        const double bw = std::min(70.0, 0.5 * plotW / static_cast<double>(n));
        cairo_set_source_rgb(cr, 0, 0, 0);
        const std::vector<std::string> label = labelLines(e.spread[k].strategy, plotW / static_cast<double>(n) - 6.0);
        for (std::size_t l = 0; l < label.size(); ++l)
            drawText(cr, cx, py + plotH + 20 + 14.0 * static_cast<double>(l), label[l], 12, 0.5);
        drawText(cr, cx, py + plotH + 38 + 14.0 * static_cast<double>(lines - 1), "n = " + std::to_string(m.count), 11,
                 0.5);
        if (m.count == 0)
            continue;
        const double *c = colours[k % 7];
        cairo_set_line_width(cr, 1.5);
        cairo_set_source_rgb(cr, c[0], c[1], c[2]);
        // whiskers to the extremes
        cairo_move_to(cr, cx, Y(m.min * scale));
        cairo_line_to(cr, cx, Y(m.q1 * scale));
        cairo_move_to(cr, cx, Y(m.q3 * scale));
        cairo_line_to(cr, cx, Y(m.max * scale));
        cairo_move_to(cr, cx - bw / 4, Y(m.min * scale));
        cairo_line_to(cr, cx + bw / 4, Y(m.min * scale));
        cairo_move_to(cr, cx - bw / 4, Y(m.max * scale));
        cairo_line_to(cr, cx + bw / 4, Y(m.max * scale));
        cairo_stroke(cr);
        // the box: quartiles, median
        cairo_rectangle(cr, cx - bw / 2, Y(m.q3 * scale), bw, Y(m.q1 * scale) - Y(m.q3 * scale));
        cairo_set_source_rgba(cr, c[0], c[1], c[2], 0.35);
        cairo_fill_preserve(cr);
        cairo_set_source_rgb(cr, c[0], c[1], c[2]);
        cairo_stroke(cr);
        cairo_set_line_width(cr, 3.0);
        cairo_set_source_rgb(cr, 0, 0, 0);
        cairo_move_to(cr, cx - bw / 2, Y(m.median * scale));
        cairo_line_to(cr, cx + bw / 2, Y(m.median * scale));
        cairo_stroke(cr);
        // the mean
        cairo_arc(cr, cx, Y(m.mean * scale), 3.5, 0, 2 * M_PI);
        cairo_fill(cr);
    }
}
} // namespace

void writeExecutionPlot(const std::string &path, const ExecutionResult &e, const MissionSpec &m, bool svg)
{
    const bool metric = m.physicalUnits().length;
    const bool hours = m.physicalUnits().time;
    const double lengthScale = metric ? m.metresPerUnit() / 1000.0 : 1.0;
    const double timeScale = hours ? m.timeUnitSeconds / 3600.0 : 1.0;
    const std::string lengthAxis = metric ? "km" : "length units";
    const std::string timeAxis = hours ? "h" : "time units";
    const int W = 2 * kPanelW, H = kPanelH + 40;
    writeCairoFile(path, W, H, svg, [&](void *ctx) {
        cairo_t *cr = static_cast<cairo_t *>(ctx);
        cairo_set_source_rgb(cr, 1, 1, 1);
        cairo_paint(cr);
        panel(cr, 0, 0, e, "distance to goal at the planned arrival", "distance (" + lengthAxis + ")", lengthScale,
              &StrategySpread::finalDistance);
        panel(cr, kPanelW, 0, e, "arrival within the radius minus the planned arrival", "delay (" + timeAxis + ")",
              timeScale, &StrategySpread::arrivalDelay);
        std::size_t runs = 0;
        for (const ExecutionRun &r : e.runs)
            runs += r.planned ? 1 : 0;
        char note[256];
        std::snprintf(note, sizeof note,
                      "%zu runs flown in %s, surfacing every %g %s; boxes: quartiles, bar: median, dot: mean, "
                      "whiskers: extremes",
                      runs, e.truth.c_str(), e.surfacingInterval * (hours ? timeScale : 1.0), timeAxis.c_str());
        cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
        drawText(cr, 20, H - 14, note, 12, 0.0);
    });
}
} // namespace ompl_glider
