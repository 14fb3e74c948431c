// Map rendering: SVG and PNG files are written and valid, the path colour is really drawn (pixel check through
// cairo), polygons are filled, and bad input raises ompl_glider::Error.
#include <gtest/gtest.h>

#include <cairo.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>

#include "ompl_glider/Exception.h"
#include "ompl_glider/current/CurrentField.h"
#include "ompl_glider/current/LocalProjection.h"
#include "ompl_glider/current/MeanderingJet.h"
#include "ompl_glider/output/MapRenderer.h"

using namespace ompl_glider;
namespace fs = std::filesystem;

namespace
{
Region jetRegion()
{
    Region r;
    r.xMin = 0;
    r.xMax = 10;
    r.yMin = -4;
    r.yMax = 4;
    return r;
}

std::string readAll(const fs::path &p)
{
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// Number of pixels of the PNG within +-tol of the colour (r, g, b) in 0..255.
long countColour(const fs::path &png, int r, int g, int b, int tol = 3)
{
    cairo_surface_t *s = cairo_image_surface_create_from_png(png.c_str());
    EXPECT_EQ(cairo_surface_status(s), CAIRO_STATUS_SUCCESS);
    const int w = cairo_image_surface_get_width(s), h = cairo_image_surface_get_height(s);
    const int stride = cairo_image_surface_get_stride(s);
    const unsigned char *data = cairo_image_surface_get_data(s);
    long n = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
        {
            const auto px = *reinterpret_cast<const uint32_t *>(data + y * stride + 4 * x);
            const int pr = (px >> 16) & 255, pg = (px >> 8) & 255, pb = px & 255;
            n += std::abs(pr - r) <= tol && std::abs(pg - g) <= tol && std::abs(pb - b) <= tol;
        }
    cairo_surface_destroy(s);
    return n;
}

fs::path tempDir(const std::string &name)
{
    const fs::path d = fs::temp_directory_path() / ("ompl_glider_map_" + name + "_" + std::to_string(::getpid()));
    fs::create_directories(d);
    return d;
}
} // namespace

TEST(MapRenderer, WritesValidSvgAndPngWithThePath)
{
    const fs::path dir = tempDir("ok");
    MapRenderer map(jetRegion());
    map.setField(std::make_shared<MeanderingJet>(), 0.0);
    map.addPolygon({"island A", {{4, -3.5}, {5.5, -3.5}, {5, -2.5}}, {0.55, 0.50, 0.45, 1.0}, {0.3, 0.25, 0.2, 1}});
    MapPath p = MapRenderer::refinedPathStyle("refined", {{1, -3, 0}, {3, 0, 4}, {8, 3, 12}});
    p.colour = {1.0, 0.85, 0.0, 1.0}; // a colour used nowhere else
    map.addPath(p);
    map.setStartGoal(1, -3, 8, 3);
    map.addNote("travel time 12");
    map.writeSvg((dir / "map.svg").string());
    map.writePng((dir / "map.png").string());

    const std::string svg = readAll(dir / "map.svg");
    ASSERT_GT(svg.size(), 1000u);
    EXPECT_NE(svg.find("<svg"), std::string::npos);
    EXPECT_NE(svg.find("</svg>"), std::string::npos);
    const std::string png = readAll(dir / "map.png");
    ASSERT_GT(png.size(), 1000u);
    EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));

    // Pixel checks: the path colour is drawn (a 3-px line over ~700 px of track), the island's fill at its centroid.
    EXPECT_GT(countColour(dir / "map.png", 255, 217, 0), 500);
    EXPECT_GT(countColour(dir / "map.png", 140, 128, 115, 2), 100);
    cairo_surface_t *s = cairo_image_surface_create_from_png((dir / "map.png").c_str());
    EXPECT_EQ(cairo_image_surface_get_width(s), map.size().first);
    EXPECT_EQ(cairo_image_surface_get_height(s), map.size().second);
    cairo_surface_destroy(s);
    fs::remove_all(dir);
}

TEST(MapRenderer, WithoutPathNoPathColour)
{
    const fs::path dir = tempDir("nopath");
    MapRenderer map(jetRegion());
    map.setField(std::make_shared<MeanderingJet>(), 3.0);
    map.writePng((dir / "map.png").string());
    EXPECT_EQ(countColour(dir / "map.png", 255, 217, 0), 0);
    fs::remove_all(dir);
}

TEST(MapRenderer, BadInputRaisesError)
{
    Region bad = jetRegion();
    bad.xMax = bad.xMin;
    EXPECT_THROW(MapRenderer{bad}, Error);
    MapRenderer map(jetRegion());
    EXPECT_THROW(map.addPolygon({"two points", {{0, 0}, {1, 1}}}), Error);
    EXPECT_THROW(map.writePng("/nonexistent-dir/x/map.png"), Error);
    EXPECT_THROW(map.writeSvg("/nonexistent-dir/x/map.svg"), Error);
}

TEST(MapRenderer, GeographicFrameDrawsMeridiansWhereTheProjectionPutsThem)
{
    // a 300 km square about 77W 18N in the local azimuthal frame; the graticule step for ~2.8 degrees is 0.5
    // degrees, so the meridian 76.5W crosses the plot at x = forward(-76.5, 18).x, which is no multiple of the metre
    // grid's 50 km: only the geographic map has a line in that pixel column
    const auto proj = std::make_shared<LocalProjection>(-77.0, 18.0);
    Region r;
    r.xMin = -150000;
    r.xMax = 150000;
    r.yMin = -150000;
    r.yMax = 150000;
    MapOptions geo;
    geo.toGeographic = [proj](Point2 p) { return proj->inverse(p.x, p.y); };
    geo.toLocal = [proj](LonLat g) { return proj->forward(g.lon, g.lat); };
    geo.metresPerUnit = 1.0;
    const fs::path dir = tempDir("geo");
    MapRenderer withGrid(r, geo), plain(r);
    withGrid.writePng((dir / "geo.png").string());
    plain.writePng((dir / "plain.png").string());
    const double xm = proj->forward(-76.5, 18.0).x;
    ASSERT_GT(std::abs(std::remainder(xm, 50000.0)), 2000.0); // 5 px from the nearest metre grid line
    const auto [w, h] = withGrid.size();
    const double plotW = w - 72 - 270, scale = plotW / 300000.0; // the renderer's margins (kLeft, kRight)
    const int col = int(std::lround(72 + (xm - r.xMin) * scale));
    auto darkInColumn = [&](const fs::path &png) {
        cairo_surface_t *s = cairo_image_surface_create_from_png(png.c_str());
        const int stride = cairo_image_surface_get_stride(s);
        const unsigned char *data = cairo_image_surface_get_data(s);
        int rows = 0;
        for (int y = 52 + 40; y < 52 + int(300000 * scale) - 60; ++y) // inside the plot, clear of the scale bar
        {
            bool dark = false;
            for (int x = col - 1; x <= col + 1; ++x)
            {
                const auto px = *reinterpret_cast<const uint32_t *>(data + y * stride + 4 * x);
                dark = dark || ((px >> 8) & 255) < 235;
            }
            rows += dark;
        }
        cairo_surface_destroy(s);
        return rows;
    };
    const int plotRows = int(300000 * scale) - 100;
    EXPECT_GT(darkInColumn(dir / "geo.png"), plotRows * 9 / 10);
    EXPECT_LT(darkInColumn(dir / "plain.png"), 12); // only where the metre grid's horizontal lines cross it
    EXPECT_EQ(w, plain.size().first);
    fs::remove_all(dir);
}

namespace
{
/// The y of the <text> element holding exactly @p s in the SVG (its device y: the maps' texts have no transform
/// but the identity), or -1 when there is none.
double textY(const std::string &svg, const std::string &s)
{
    const std::size_t at = svg.find(">" + s + "</text>");
    if (at == std::string::npos)
        return -1;
    const std::size_t open = svg.rfind("<text ", at), y = svg.find(" y=\"", open);
    return std::stod(svg.substr(y + 4));
}

std::size_t occurrences(const std::string &text, const std::string &s)
{
    std::size_t n = 0;
    for (std::size_t at = text.find(s); at != std::string::npos; at = text.find(s, at + 1))
        ++n;
    return n;
}

/// 250 small triangles over the jet's box (a coastline's worth of polygons).
std::vector<MapPolygon> manyPolygons(bool asCoastline)
{
    std::vector<MapPolygon> out;
    for (int k = 0; k < 250; ++k)
    {
        const double x = 0.5 + 9.0 * (k % 25) / 25.0, y = -3.5 + 7.0 * (k / 25) / 10.0;
        MapPolygon p;
        p.vertices = {{x, y}, {x + 0.2, y}, {x + 0.1, y + 0.2}};
        p.label = asCoastline ? "" : "islet " + std::to_string(k);
        p.legend = asCoastline ? "land (coastline)" : "";
        out.push_back(p);
    }
    return out;
}
} // namespace

TEST(MapRenderer, ACoastlineOfManyPolygonsKeepsTheLegendColourBarAndNotesOnThePageAsText)
{
    const fs::path dir = tempDir("coast");
    for (const bool asCoastline : {true, false})
    {
        MapRenderer map(jetRegion());
        map.setField(std::make_shared<MeanderingJet>(), 0.0);
        for (const MapPolygon &p : manyPolygons(asCoastline))
            map.addPolygon(p);
        map.setStartGoal(1, -3, 8, 3);
        map.addNote("travel time 12");
        map.writeSvg((dir / "map.svg").string());
        const std::string svg = readAll(dir / "map.svg");
        const double H = map.size().second;
        // text is text: the legend, the colour bar's label and the note are <text> elements on the page
        for (const std::string s : {"Legend", "current speed", "travel time 12"})
        {
            const double y = textY(svg, s);
            EXPECT_GT(y, 0) << s;
            EXPECT_LT(y, H) << s;
        }
        if (asCoastline)
        {
            EXPECT_EQ(occurrences(svg, ">land (coastline)</text>"), 1u); // one entry, no labels on the map
            EXPECT_EQ(occurrences(svg, "islet"), 0u);
        }
        else
        {
            // at most 8 regions in the legend, the rest counted
            std::size_t entries = 0;
            for (int k = 0; k < 250; ++k)
                entries += occurrences(svg, ">islet " + std::to_string(k) + "</text>") > 1;
            EXPECT_LE(entries, 8u);
            EXPECT_NE(svg.find(">and 242 more regions</text>"), std::string::npos);
        }
    }
    fs::remove_all(dir);
}

namespace
{
/// A uniform current: @p u east everywhere.
class MapUniformEast : public CurrentField
{
public:
    explicit MapUniformEast(double u) : u_(u) {}
    double maxSpeed(const Region &) const override { return std::abs(u_); }
    std::string name() const override { return "uniform"; }

protected:
    Velocity evaluate(double, double, double, double) const override { return {u_, 0.0}; }
    Jacobian evaluateJacobian(double, double, double, double) const override { return {}; }

private:
    double u_;
};

/// The SVG's texts in the order written, joined by spaces.
std::string svgTexts(const std::string &svg)
{
    std::string out;
    for (std::size_t at = svg.find("<text "); at != std::string::npos; at = svg.find("<text ", at + 1))
    {
        const std::size_t open = svg.find('>', at), close = svg.find("</text>", open);
        out += (out.empty() ? "" : " ") + svg.substr(open + 1, close - open - 1);
    }
    return out;
}

/// The pixel (r, g, b) at (x, y) of a PNG.
std::array<int, 3> mapPixelAt(const fs::path &png, int x, int y)
{
    cairo_surface_t *s = cairo_image_surface_create_from_png(png.c_str());
    const auto px = *reinterpret_cast<const uint32_t *>(cairo_image_surface_get_data(s) +
                                                        y * cairo_image_surface_get_stride(s) + 4 * x);
    cairo_surface_destroy(s);
    return {int((px >> 16) & 255), int((px >> 8) & 255), int(px & 255)};
}

/// The columns [x0, x1] of the first and last pixel of a PNG that is pure magenta (within a tolerance), or {-1, -1}.
std::pair<int, int> mapMagentaColumns(const fs::path &png)
{
    cairo_surface_t *s = cairo_image_surface_create_from_png(png.c_str());
    const int w = cairo_image_surface_get_width(s), h = cairo_image_surface_get_height(s);
    const int stride = cairo_image_surface_get_stride(s);
    const unsigned char *data = cairo_image_surface_get_data(s);
    int lo = -1, hi = -1;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w - 300; ++x) // the plot, not the legend's key
        {
            const auto px = *reinterpret_cast<const uint32_t *>(data + y * stride + 4 * x);
            if (((px >> 16) & 255) > 200 && ((px >> 8) & 255) < 90 && (px & 255) > 200)
            {
                lo = lo < 0 ? x : std::min(lo, x);
                hi = std::max(hi, x);
            }
        }
    cairo_surface_destroy(s);
    return {lo, hi};
}
} // namespace

TEST(MapRenderer, OneTickSeriesWithItsUnit)
{
    // two paths that both ask for ticks (a plan and the track flown over it): the ticks of the last one only, in
    // hours after the departure
    const fs::path dir = tempDir("ticks");
    MapOptions o;
    o.tickUnit = "h";
    o.tickNote = "ticks: hours after the departure";
    o.tickInterval = 2.0;
    MapRenderer map(jetRegion(), o);
    map.addPath(MapRenderer::refinedPathStyle("plan", {{1, -3, 0}, {8, 3, 10}}));
    MapPath track = MapRenderer::refinedPathStyle("track", {{1, -3, 0}, {4, 0, 5}, {8, 3, 10}});
    map.addPath(track);
    map.writeSvg((dir / "map.svg").string());
    const std::string svg = readAll(dir / "map.svg");
    for (const char *tick : {">+2 h</text>", ">+4 h</text>", ">+6 h</text>", ">+8 h</text>"})
        EXPECT_EQ(occurrences(svg, tick), 1u) << tick;
    EXPECT_EQ(occurrences(svg, ">t="), 0u); // no second series in another unit
    EXPECT_EQ(occurrences(svg, ">ticks: hours after the departure</text>"), 1u);
    fs::remove_all(dir);
}

TEST(MapRenderer, TheLegendStaysInsideThePicture)
{
    // a long path label and many notes: wrapped at the right edge, and the page as tall as the legend
    const fs::path dir = tempDir("legend");
    MapRenderer map(jetRegion());
    map.setField(std::make_shared<MeanderingJet>(), 0.0);
    MapPath p = MapRenderer::refinedPathStyle(
        "a very long legend entry that no margin of 270 pixels holds on one line, however small its font",
        {{1, -3, 0}, {8, 3, 12}});
    map.addPath(p);
    for (int k = 0; k < 40; ++k)
        map.addNote("note " + std::to_string(k) + ": a line of the legend's notes that is long enough to wrap");
    map.writePng((dir / "map.png").string());
    const auto [w, h] = map.size();
    EXPECT_GT(h, 40 * 2 * 18); // 40 notes of two lines each fit
    // nothing dark in the last 4 columns or the last 4 rows: no text cut at an edge
    cairo_surface_t *png = cairo_image_surface_create_from_png((dir / "map.png").c_str());
    ASSERT_EQ(cairo_image_surface_get_height(png), h);
    const int stride = cairo_image_surface_get_stride(png);
    const unsigned char *data = cairo_image_surface_get_data(png);
    long dark = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            if (x >= w - 4 || y >= h - 4)
            {
                const auto px = *reinterpret_cast<const uint32_t *>(data + y * stride + 4 * x);
                dark += int((px >> 16) & 255) + int((px >> 8) & 255) + int(px & 255) < 3 * 200;
            }
    cairo_surface_destroy(png);
    EXPECT_EQ(dark, 0);
    fs::remove_all(dir);
}

TEST(MapRenderer, MeasuredCurrentsAreArrowsAtTheCurrentArrowsScaleWithAKey)
{
    // a uniform current of 0.4 everywhere: its arrows are 0.9 of a cell long; a measured current of 0.2 east is half
    // that, one of 0.4 as long
    const Region r = jetRegion();
    const double plotW = 1100 - 72 - 270, scale = plotW / 10.0;   // the page's margins (kLeft, kRight)
    const double dx = 10.0 / 26, dy = 8.0 / std::round(8.0 / dx); // 26 arrow columns
    const double cell = std::min(dx, dy) * scale;
    const fs::path dir = tempDir("vectors");
    for (const double speed : {0.2, 0.4})
    {
        MapOptions o;
        o.speedShading = false;
        o.speedInMetresPerSecond = true;
        MapRenderer map(r, o);
        map.setField(std::make_shared<MapUniformEast>(0.4), 0.0);
        MapVectors v;
        v.label = "glider: 1 measured DAC";
        v.at = {{5.0, 0.2}};
        v.velocity = {{speed, 0.0}};
        v.colour = {1.0, 0.0, 1.0, 1.0};
        map.addVectors(v);
        map.writePng((dir / "map.png").string());
        const auto [lo, hi] = mapMagentaColumns(dir / "map.png");
        ASSERT_GE(lo, 0);
        EXPECT_NEAR(lo, 72 + 5.0 * scale, 1.5); // from where it was measured
        EXPECT_NEAR(hi - lo, 0.9 * cell * speed / 0.4, 2.0) << speed;
        map.writeSvg((dir / "map.svg").string());
        const std::string svg = readAll(dir / "map.svg");
        // the key: an arrow of the largest round speed (1, 2, 5 x 10^k) not above the fastest, with its value, for
        // the field's arrows (0.4: 0.2) and the measured ones (the legend's lines joined where they were wrapped)
        const std::string text = svgTexts(readAll(dir / "map.svg"));
        EXPECT_NE(text.find("glider: 1 measured DAC: arrow 0.2 m/s (0.39 kn)"), std::string::npos) << text;
        EXPECT_NE(text.find("current at t=0, arrow 0.2 m/s (0.39 kn)"), std::string::npos) << text;
    }
    MapRenderer map(r);
    EXPECT_THROW(map.addVectors({"two tails, one velocity", {{1, 1}, {2, 2}}, {{0.1, 0.0}}}), Error);
    fs::remove_all(dir);
}

TEST(MapRenderer, TheGridFillsColourAtANodeFollowsItsValue)
{
    // 5 x 4 nodes 2 units apart (off the grid's lines), p = (i + j) / 7; no field under it: the page's white shows
    // through the fill's alpha
    MapGridFill f;
    f.label = "probability of reach by +2.00 d";
    f.x0 = 1.0;
    f.y0 = -2.5;
    f.h = 2.0;
    f.nx = 5;
    f.ny = 4;
    for (int j = 0; j < f.ny; ++j)
        for (int i = 0; i < f.nx; ++i)
            f.values.push_back(float((i + j) / 7.0));
    const fs::path dir = tempDir("fill");
    MapRenderer map(jetRegion());
    map.setGridFill(f);
    map.writePng((dir / "map.png").string());
    const double scale = (1100 - 72 - 270) / 10.0;
    int checked = 0;
    for (int j = 0; j < f.ny; ++j)
        for (int i = 0; i < f.nx; ++i)
        {
            const double x = f.x0 + i * f.h, y = f.y0 + j * f.h;
            if (x >= 10.0 || y >= 4.0 || (i + j) == 0)
                continue;
            const int px = int(std::lround(72 + x * scale - 0.5)), py = int(std::lround(52 + (4.0 - y) * scale - 0.5));
            const Rgba c = fillColour(f.values[std::size_t(j * f.nx + i)]);
            const auto got = mapPixelAt(dir / "map.png", px, py);
            const double want[3] = {255 * (1 - c.a + c.a * c.r), 255 * (1 - c.a + c.a * c.g),
                                    255 * (1 - c.a + c.a * c.b)};
            for (int k = 0; k < 3; ++k)
                EXPECT_NEAR(got[k], want[k], 12) << "node " << i << "," << j << " channel " << k;
            ++checked;
        }
    EXPECT_GE(checked, 10);
    // the more likely, the darker: p = 1 is darker than p = 0.25 in every channel but red's
    EXPECT_LT(fillColour(1.0).g, fillColour(0.25).g);
    EXPECT_GT(fillColour(1.0).a, fillColour(0.25).a);
    const std::string svgPath = (dir / "map.svg").string();
    map.writeSvg(svgPath);
    EXPECT_NE(readAll(svgPath).find(">probability of reach by +2.00 d</text>"), std::string::npos);
    EXPECT_THROW(map.setGridFill({"bad", 0, 0, 1.0, 2, 2, {0.5f}}), Error);
    fs::remove_all(dir);
}
