/// @file MapCairo.cpp
/// @brief The cairo drawing primitives shared by the maps and plots (text, as SVG <text> elements in an SVG; arrows,
/// markers, number and degree labels) and the writing of a drawing as an SVG or PNG file (writeCairoFile()). The
/// map's plot area: MapRenderer.cpp; grid and axes: MapRendererAxes.cpp; legend: MapRendererLegend.cpp.
#include "ompl_glider/output/MapRenderer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

#include <cairo-svg.h>
#include <cairo.h>

#include "ompl_glider/Exception.h"
#include "../io/TextUtil.h"
#include "MapPainter.h"
#include "OutputDirectory.h"

namespace ompl_glider
{
namespace map_detail
{
namespace
{
/// Selects the sans-serif font of @p size, bold or normal.
void selectFont(cairo_t *cr, double size, bool bold)
{
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL,
                           bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, size);
}

/// Text of an SVG map, written as <text> elements (searchable, selectable, small) rather than cairo's glyph
/// outlines: attached to the SVG surface as user data; the text helpers write to it instead of drawing.
cairo_user_data_key_t svgTextKey;

/// Writes @p s as an SVG <text> element when @p cr draws on an SVG surface with a text buffer; false otherwise.
bool svgText(cairo_t *cr, double x, double y, const std::string &s, double size, bool bold, double alignX,
             const Rgba &c, bool halo)
{
    auto *out = static_cast<std::string *>(cairo_surface_get_user_data(cairo_get_target(cr), &svgTextKey));
    if (!out)
        return false;
    cairo_matrix_t m;
    cairo_get_matrix(cr, &m);
    const char *anchor = alignX >= 0.75 ? "end" : alignX >= 0.25 ? "middle" : "start";
    char head[512];
    std::snprintf(head, sizeof head,
                  "<text transform=\"matrix(%g %g %g %g %g %g)\" x=\"%.2f\" y=\"%.2f\" font-family=\"sans-serif\" "
                  "font-size=\"%g\"%s text-anchor=\"%s\" fill=\"rgb(%d,%d,%d)\" fill-opacity=\"%g\"%s>",
                  m.xx, m.yx, m.xy, m.yy, m.x0, m.y0, x, y, size, bold ? " font-weight=\"bold\"" : "", anchor,
                  int(std::lround(255 * c.r)), int(std::lround(255 * c.g)), int(std::lround(255 * c.b)), c.a,
                  halo ? " stroke=\"white\" stroke-opacity=\"0.85\" stroke-width=\"3\" stroke-linejoin=\"round\" "
                         "paint-order=\"stroke\""
                       : "");
    *out += head + text::xmlEscaped(s) + "</text>\n";
    return true;
}

/// The advance of @p s in the current font.
double textAdvance(cairo_t *cr, const std::string &s)
{
    cairo_text_extents_t ext;
    cairo_text_extents(cr, text::validUtf8(s).c_str(), &ext); // cairo stops drawing after invalid UTF-8
    return ext.x_advance;
}
} // namespace

double niceStep(double raw)
{
    if (!(raw > 0.0) || !std::isfinite(raw))
        return 1.0;
    const double p = std::pow(10.0, std::floor(std::log10(raw)));
    const double m = raw / p;
    return p * (m <= 1.0 ? 1.0 : m <= 2.0 ? 2.0 : m <= 5.0 ? 5.0 : 10.0);
}

std::string fmt(double v, int prec)
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
                  v == 0.0 || (!east && std::abs(v) < 1e-9) ? ""
                  : east                                    ? (v < 0 ? "W" : "E")
                                                            : (v < 0 ? "S" : "N"));
    return buf;
}

void setColour(cairo_t *cr, const Rgba &c)
{
    cairo_set_source_rgba(cr, c.r, c.g, c.b, c.a);
}

void setDash(cairo_t *cr, bool dashed)
{
    if (dashed)
    {
        const double dash[] = {6.0, 4.0};
        cairo_set_dash(cr, dash, 2, 0);
    }
}

void haloText(cairo_t *cr, double x, double y, const std::string &raw, const Rgba &c, double size, bool bold,
              double alignX)
{
    const std::string s = text::validUtf8(raw); // cairo stops drawing after invalid UTF-8
    if (svgText(cr, x, y, s, size, bold, alignX, c, true))
        return;
    selectFont(cr, size, bold);
    const double x0 = x - alignX * textAdvance(cr, s);
    cairo_move_to(cr, x0, y);
    cairo_text_path(cr, s.c_str());
    cairo_set_source_rgba(cr, 1, 1, 1, 0.85);
    cairo_set_line_width(cr, 3.0);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    cairo_stroke(cr);
    cairo_move_to(cr, x0, y);
    setColour(cr, c);
    cairo_show_text(cr, s.c_str());
    cairo_new_path(cr); // show_text leaves a current point: do not let the next arc connect to it
}

void plainText(cairo_t *cr, double x, double y, const std::string &raw, double size, bool bold, double alignX, Rgba c)
{
    const std::string s = text::validUtf8(raw); // cairo stops drawing after invalid UTF-8
    if (svgText(cr, x, y, s, size, bold, alignX, c, false))
        return;
    selectFont(cr, size, bold);
    cairo_move_to(cr, x - alignX * textAdvance(cr, s), y);
    setColour(cr, c);
    cairo_show_text(cr, s.c_str());
    cairo_new_path(cr); // show_text leaves a current point: do not let the next arc connect to it
}

int wrappedText(cairo_t *cr, double x, double y, const std::string &s, double size, double maxWidth, double lineHeight,
                Rgba c)
{
    selectFont(cr, size, false);
    std::vector<std::string> lines;
    std::string rest = s;
    while (!rest.empty())
    {
        if (textAdvance(cr, rest) <= maxWidth)
        {
            lines.push_back(rest);
            break;
        }
        // longest prefix that fits, preferring to break after a space
        std::size_t fit = 1;
        while (fit < rest.size() && textAdvance(cr, rest.substr(0, fit + 1)) <= maxWidth)
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

void waypointMarker(cairo_t *cr, double x, double y, double radius, const Rgba &colour)
{
    cairo_new_path(cr);
    cairo_arc(cr, x, y, radius, 0, 2 * kPi);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_fill_preserve(cr);
    setColour(cr, colour);
    cairo_set_line_width(cr, 1.3);
    cairo_stroke(cr);
}

void traceStar(cairo_t *cr, double cx, double cy, double outer, double inner)
{
    cairo_new_path(cr);
    for (int k = 0; k < 10; ++k)
    {
        const double r = k % 2 ? inner : outer, a = -kPi / 2 + k * kPi / 5;
        k == 0 ? cairo_move_to(cr, cx + r * std::cos(a), cy + r * std::sin(a))
               : cairo_line_to(cr, cx + r * std::cos(a), cy + r * std::sin(a));
    }
    cairo_close_path(cr);
}
} // namespace map_detail

void drawCairoText(void *cairo, double x, double y, const std::string &text, double size, bool bold, double alignX,
                   Rgba colour)
{
    map_detail::plainText(static_cast<cairo_t *>(cairo), x, y, text, size, bold, alignX, colour);
}

double niceAxisStep(double raw)
{
    return map_detail::niceStep(raw);
}

namespace
{
cairo_status_t appendToString(void *closure, const unsigned char *data, unsigned int length)
{
    static_cast<std::string *>(closure)->append(reinterpret_cast<const char *>(data), length);
    return CAIRO_STATUS_SUCCESS;
}
} // namespace

void writeCairoFile(const std::string &filename, int width, int height, bool svg,
                    const std::function<void(void *)> &draw)
{
    // Drawn into memory, then written by the output layer's checked write (a full disk is an error, not a short
    // file).
    std::string bytes;
    cairo_surface_t *surf = svg ? cairo_svg_surface_create_for_stream(appendToString, &bytes, width, height)
                                : cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height);
    if (cairo_surface_status(surf) != CAIRO_STATUS_SUCCESS)
    {
        const std::string msg = cairo_status_to_string(cairo_surface_status(surf));
        cairo_surface_destroy(surf);
        throw Error("cannot create '" + filename + "': " + msg);
    }
    std::string texts; // the SVG's text, as <text> elements
    if (svg)
        cairo_surface_set_user_data(surf, &map_detail::svgTextKey, &texts, nullptr);
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
        st = cairo_surface_write_to_png_stream(surf, appendToString, &bytes);
    }
    cairo_surface_destroy(surf);
    if (st != CAIRO_STATUS_SUCCESS)
        throw Error("cannot write '" + filename + "': " + cairo_status_to_string(st));
    if (svg)
    {
        const std::size_t end = bytes.rfind("</svg>");
        if (end == std::string::npos)
            throw Error("cannot write '" + filename + "': cairo's SVG has no </svg>");
        bytes.insert(end, "<g id=\"text\">\n" + texts + "</g>\n");
    }
    output_detail::writeFileChecked(filename, bytes);
}
} // namespace ompl_glider
