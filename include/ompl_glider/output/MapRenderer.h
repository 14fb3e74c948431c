#pragma once
/// @file MapRenderer.h
/// @brief A map for the pilot: the current field, forbidden regions, planned paths with time ticks,
/// start and goal, legend and axes; written as SVG and PNG (cairo).

#include <memory>
#include <optional>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "ompl_glider/Geometry.h"
#include "ompl_glider/current/CurrentField.h"

namespace ompl_glider
{
namespace map_detail
{
class MapPainter;
}

/// @brief Writes a drawing as SVG (@p svg) or PNG of @p width x @p height pixels: @p draw gets the cairo_t.
/// @throws Error naming the file when it cannot be written.
void writeCairoFile(const std::string &filename, int width, int height, bool svg,
                    const std::function<void(void *)> &draw);

/// @brief A colour with alpha, components in [0, 1].
struct Rgba
{
    double r{0.0};
    double g{0.0};
    double b{0.0};
    double a{1.0};
};

/// @brief Text at (x, y) (baseline) on a cairo_t, aligned by @p alignX (0 left, 0.5 centre, 1 right): the maps' and
/// plots' one text routine.
void drawCairoText(void *cairo, double x, double y, const std::string &text, double size, bool bold = false,
                   double alignX = 0.0, Rgba colour = {0.1, 0.1, 0.1, 1.0});

/// @brief A round axis step (1, 2, 5 x 10^k) at least @p raw (1 for a raw step that is not positive and finite).
double niceAxisStep(double raw);

/// @brief A forbidden region (land, restricted area, ice zone ...) drawn as a filled polygon.
struct MapPolygon
{
    std::string label;                  ///< shown at the polygon's centroid and in the legend
    std::vector<Point2> vertices;       ///< (x, y) in field coordinates, at least 3
    Rgba fill{0.55, 0.50, 0.45, 0.55};  ///< fill colour (default: land brown-grey, translucent)
    Rgba stroke{0.30, 0.25, 0.20, 1.0}; ///< outline colour
    bool hatched{false};                ///< draw diagonal hatching (e.g. for time-windowed zones)
    std::string legend{};               ///< the legend's entry when it differs from label (a
                                        ///< coastline's many polygons: one entry, no labels)
};

/// @brief A path drawn as a polyline through its waypoints.
struct MapPath
{
    std::string label;                  ///< legend entry ("ZA*TVE raw", "smoothed", ...); empty: none
    std::vector<TimedPoint> waypoints;  ///< positions and arrival times
    Rgba colour{0.85, 0.10, 0.10, 1.0}; ///< line colour
    double width{2.5};                  ///< line width in pixels
    bool dashed{false};                 ///< dashed line
    bool waypointMarkers{true};         ///< small circles at the waypoints
    /// time ticks (and labels) along the path, see MapOptions::tickInterval; of the paths that ask for them, the
    /// last one added gets them (one tick series on a map)
    bool timeTicks{false};
};

/// @brief Measured currents (a glider's depth-averaged currents) drawn as arrows from where each was measured, at
/// the scale of the field's current arrows (the same speed gives the same length), with a key in the legend: an arrow
/// of a round speed and its value.
struct MapVectors
{
    std::string label;                   ///< the legend's entry ("glider: 8 measured DAC")
    std::vector<Point2> at;              ///< the arrows' tails (field coordinates)
    std::vector<Velocity> velocity;      ///< one per tail, in the field's velocity unit (m/s for a forecast)
    Rgba colour{0.42, 0.11, 0.60, 0.95}; ///< purple
};

/// @brief A value in [0, 1] on the nodes (x0 + i h, y0 + j h) of a grid (a probability of reach), drawn as a colour
/// fill under the paths: a cell of side h about each node in fillColour() of its value (nothing where it is 0), and a
/// colour bar from 0 to 1 in the legend.
struct MapGridFill
{
    std::string label;         ///< the colour bar's label ("probability of reach by +2.0 d")
    double x0{0.0}, y0{0.0};   ///< node (0, 0) (field coordinates)
    double h{0.0};             ///< node spacing
    int nx{0}, ny{0};          ///< node counts
    std::vector<float> values; ///< node (i, j) at j * nx + i, in [0, 1]
};

/// @brief The grid fill's colour of a value @p p in [0, 1], alpha included: a translucent light yellow at small p to a
/// near-opaque dark red at 1 (values outside [0, 1] are clamped).
Rgba fillColour(double p);

/// @brief Page and field-drawing options.
struct MapOptions
{
    int width{1100};                  ///< image width in pixels (the height follows from the region's aspect ratio)
    int arrowColumns{26};             ///< current arrows across the region's width
    double tickInterval{0.0};         ///< time between ticks along paths; <= 0: a round value giving about 10 ticks
    std::string title;                ///< drawn above the map
    std::string timeUnit;             ///< appended to times in labels ("s", "h", or empty for dimensionless fields)
    bool speedShading{true};          ///< shade the background by current speed
    bool arrows{true};                ///< draw current arrows (off for a field whose "velocity" is a scalar in u)
    std::string shadingLabel;         ///< label of the colour bar; empty: "current speed"
    std::string fieldWord{"current"}; ///< what the field is, in the legend: "current" or "wind"
    std::function<std::string(double)> timeText; ///< a field time as a pilot reads it (a date); empty: "t=..."
    /// The time ticks' unit after the departure ("h", "d"): the paths' times are that many units after the
    /// departure and a tick reads "+6 h"; empty: a tick reads "t=6" and timeUnit
    std::string tickUnit;
    /// The legend's note on the ticks; empty: "ticks: time along the path"
    std::string tickNote;
    /// Geographic frame (both set): the axes are labelled in longitude/latitude and a graticule of meridians and
    /// parallels is drawn through the field's frame (curved where the projection bends them); start and goal are
    /// given in degrees and a scale bar is drawn. Unset: the field's x/y frame.
    std::function<LonLat(Point2)> toGeographic;
    std::function<Point2(LonLat)> toLocal;
    double metresPerUnit{0.0};          ///< > 0: the frame is in metres times this (scale bar); 0: no scale bar
    bool speedInMetresPerSecond{false}; ///< label the colour bar "m/s" and give its top in knots too
};

/// @brief Renders a map of one planning problem. Coordinates are the field's (x east, y north); the map keeps
/// the aspect ratio 1:1. Usage: set the region, the field (and the time at which it is drawn), add polygons and
/// paths, set start and goal, then writeSvg() / writePng().
class MapRenderer
{
public:
    /// @throws Error when the region's x/y bounds are not finite or empty.
    explicit MapRenderer(const Region &region, MapOptions options = {});

    /// @brief Draw the field's current at time t (and depth) as arrows over a speed shading.
    void setField(std::shared_ptr<const CurrentField> field, double time, double depth = 0.0);
    /// @brief Add a forbidden region. @throws Error with fewer than 3 vertices or non-finite coordinates.
    void addPolygon(MapPolygon polygon);
    /// @brief Add a path (drawn in the order added, later paths on top). Paths with < 1 waypoint are ignored.
    void addPath(MapPath path);
    /// @brief Start and goal markers.
    void setStartGoal(double sx, double sy, double gx, double gy);
    /// @brief A station of a mission of several legs (a via point): a square marker, its radius as a circle (in the
    /// frame's units; at least the marker's size on the page) and @p label beside it (its name and arrival date).
    void addStation(Point2 at, double radius, std::string label);
    /// @brief A free text line under the legend (e.g. "travel time 12.3").
    void addNote(std::string note);
    /// @brief Measured currents as arrows at the current arrows' scale, drawn over the paths (MapVectors). Ignored
    /// when empty. @throws Error when the tails and velocities differ in number.
    void addVectors(MapVectors vectors);
    /// @brief A value in [0, 1] on a grid drawn as a colour fill with a colour bar (MapGridFill), one per map.
    /// @throws Error when the values are not nx * ny or the spacing is not > 0.
    void setGridFill(MapGridFill fill);

    /// @brief Writes an SVG file. @throws Error when the file cannot be written.
    void writeSvg(const std::string &filename) const;
    /// @brief Writes a PNG file. @throws Error when the file cannot be written.
    void writePng(const std::string &filename) const;

    /// @brief Image size in pixels (width, height).
    std::pair<int, int> size() const;

    /// @brief Default styles for the usual path kinds.
    static MapPath rawPathStyle(std::string label, std::vector<TimedPoint> waypoints);
    static MapPath smoothedPathStyle(std::string label, std::vector<TimedPoint> waypoints);
    static MapPath refinedPathStyle(std::string label, std::vector<TimedPoint> waypoints);
    /// @brief A flown stint track ([IsernObstacles]): solid, no markers, colour @p index of a palette of 6
    /// (several methods on one map).
    static MapPath stintTrackStyle(std::string label, std::vector<TimedPoint> track, int index = 0);

private:
    /// Draws the map through map_detail::MapPainter (src/output/MapPainter.h), which reads the members below.
    friend class map_detail::MapPainter;
    void draw(void *cairoContext) const;

    Region region_;
    MapOptions options_;
    std::shared_ptr<const CurrentField> field_;
    double fieldTime_{0.0};
    double fieldDepth_{0.0};
    std::vector<MapPolygon> polygons_;
    std::vector<MapPath> paths_;
    bool hasStartGoal_{false};
    double sx_{0.0}, sy_{0.0}, gx_{0.0}, gy_{0.0};
    std::vector<std::string> notes_;
    struct Station
    {
        Point2 at;
        double radius;
        std::string label;
    };
    std::vector<Station> stations_;
    std::vector<MapVectors> vectors_;
    std::optional<MapGridFill> fill_;
};
} // namespace ompl_glider
