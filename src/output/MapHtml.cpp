// map.html (MapHtml.h): the map's data as JSON, from the result and its problem, and the page: the template
// (maphtml/map_template.html) with Leaflet and the data put in its three places.
#include "ompl_glider/output/MapHtml.h"

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include "../io/NumberText.h"
#include "JsonValues.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/current/CurrentField.h"
#include "ompl_glider/environment/KeepOffZone.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/Planning.h"
#include "ompl_glider/output/RouteFiles.h"
#include "ompl_glider/Config.h"
#include "ompl_glider/io/Time.h"
#if OMPL_GLIDER_WITH_NETCDF
#include "ompl_glider/mission/Observations.h"
#endif

namespace ompl_glider
{
namespace maphtml
{
// generated from maphtml/map_template.html and Debian's Leaflet (src/output/sources.cmake): pieces, null-terminated
extern const char *const kTemplate[];
extern const char *const kLeafletJs[];
extern const char *const kLeafletCss[];
} // namespace maphtml

namespace
{
using PageJson = nlohmann::json;

std::string joined(const char *const *pieces)
{
    std::string s;
    for (; *pieces; ++pieces)
        s += *pieces;
    return s;
}

double rounded(double v, double step)
{
    return std::isfinite(v) ? std::round(v / step) * step : v;
}

/// The map's frame: [lat, lon] (longitudes unwrapped about the region's centre, so that a trip across the antimeridian
/// stays one piece) or, without lon/lat, [y, x] in km (a forecast on metres) or the field's units.
class Frame
{
public:
    explicit Frame(const MissionProblem &p) : p_(p), geographic_(p.isGeographic())
    {
        const MissionSpec &m = p.getSpec();
        const Region &b = p.getBox();
        if (geographic_)
            lon0_ = p.toGeographic({0.5 * (b.xMin + b.xMax), 0.5 * (b.yMin + b.yMax)}).lon;
        else if (m.physicalUnits().length)
        {
            scale_ = m.metresPerUnit() / 1000.0;
            units_ = "km";
        }
    }
    PageJson at(Point2 q) const
    {
        if (!geographic_)
            return PageJson::array({rounded(q.y * scale_, 1e-6), rounded(q.x * scale_, 1e-6)});
        const LonLat g = p_.toGeographic(q);
        return PageJson::array({rounded(g.lat, 1e-6), rounded(lon0_ + std::remainder(g.lon - lon0_, 360.0), 1e-6)});
    }
    PageJson line(const std::vector<Point2> &ps) const
    {
        PageJson out = PageJson::array();
        for (const Point2 &q : ps)
            out.push_back(at(q));
        return out;
    }
    PageJson line(const std::vector<TimedPoint> &ps) const
    {
        PageJson out = PageJson::array();
        for (const TimedPoint &q : ps)
            out.push_back(at({q.x, q.y}));
        return out;
    }
    /// The planning frame's point at map coordinates (@p a, @p o): (lat, lon), or (y, x) in the map's units.
    Point2 local(double a, double o) const
    {
        return geographic_ ? p_.toLocal(LonLat{o, a}) : Point2{o / scale_, a / scale_};
    }
    bool geographic() const { return geographic_; }
    const std::string &units() const { return units_; }
    /// A length of the planning frame in the map's units (metres on a lon/lat map: Leaflet's circles).
    double length(double d) const { return geographic_ ? d * p_.getSpec().metresPerUnit() : d * scale_; }

private:
    const MissionProblem &p_;
    bool geographic_;
    double lon0_{0.0}, scale_{1.0};
    std::string units_;
};

std::string pageTime(const MissionProblem &p, double t)
{
    const std::string iso = p.isoTime(t);
    return iso.empty() ? "t = " + text::number(t, 6) : iso;
}

/// "3 d 4.2 h", "9.1 h", "12.5 min" (durationText() without its seconds), or the field's number.
std::string elapsedText(const MissionSpec &m, double dt)
{
    if (!m.physicalUnits().time)
        return text::number(dt, 6);
    const std::string s = text::durationText(dt * m.timeUnitSeconds);
    return s.substr(0, s.find(" ("));
}

/// Degrees clockwise from north of the vector (east, north).
double bearing(double e, double n)
{
    const double b = std::atan2(e, n) * 180.0 / M_PI;
    return b < 0.0 ? b + 360.0 : b;
}

/// The heading to hold at @p a for the straight leg to @p b in the current @p c at speed @p v (through the water: the
/// crab angle whose velocity cancels the current across the leg); NaN when the current across is the stronger.
double legHeading(Point2 a, Point2 b, Velocity c, double v)
{
    const double dx = b.x - a.x, dy = b.y - a.y, d = std::hypot(dx, dy);
    if (!(d > 0.0) || !(v > 0.0))
        return std::numeric_limits<double>::quiet_NaN();
    const double ex = dx / d, ey = dy / d, cross = -c.u * ey + c.v * ex; // current across the leg (left positive)
    if (std::abs(cross) >= v)
        return std::numeric_limits<double>::quiet_NaN();
    const double hp = -cross / v, ha = std::sqrt(1.0 - hp * hp); // across and along the leg, through the water
    return bearing(ha * ex - hp * ey, ha * ey + hp * ex);
}

PageJson routeJson(const MissionResult &r, const MissionProblem &p, const Frame &f)
{
    const MissionSpec &m = r.spec;
    const PlannedPath &plan = r.plan;
    PageJson route;
    route["name"] = m.name.empty() ? plan.planner : m.name;
    route["planner"] = plan.planner;
    route["travel_time"] = plan.solved ? elapsedText(m, plan.travelTime) : "no path";
    route["start"] = f.at(p.getStart());
    route["goal"] = f.at(p.getGoal());
    // a heading route's flown track (also a mission whose legs mix straight legs and held headings)
    route["points"] = plan.solved ? f.line(plan.track.size() > 1 ? plan.track : plan.path) : PageJson::array();
    PageJson wps = PageJson::array();
    const CurrentField &field = *p.getField();
    const double z = m.vehicle.depth;
    // bearings from true north where the waypoints have lon/lat (the frame's grid north turned at each point), as
    // every pilot file writes them (trueHeadings(): a held heading's true heading as it re-flies its segment)
    const std::vector<double> held = trueHeadings(r, &p);
    for (std::size_t k = 0; k < r.waypoints.size(); ++k)
    {
        const MissionWaypoint &w = r.waypoints[k];
        const PageJson pos = f.at(w.position);
        PageJson wp{{"index", k},
                    {"lat", pos[0]},
                    {"lon", pos[1]},
                    {"arrival", w.iso.empty() ? pageTime(p, w.time) : w.iso},
                    {"elapsed", elapsedText(m, w.time - plan.departure)}};
        Velocity c{std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
        if (field.inWater(w.position.x, w.position.y, z) && w.time <= field.timeEnd())
            c = field.velocity(w.position.x, w.position.y, z, w.time);
        double heading = held[k];
        if (!std::isfinite(heading) && k + 1 < r.waypoints.size() && std::isfinite(c.u))
            heading =
                trueBearing(r, &p, w.position, legHeading(w.position, r.waypoints[k + 1].position, c, plan.speed));
        wp["heading_deg"] = std::isfinite(heading) ? PageJson(rounded(heading, 0.1)) : PageJson(nullptr);
        if (std::isfinite(c.u) && std::isfinite(c.v))
        {
            // the current's direction from true north, and its components east and north
            const double speed = std::hypot(c.u, c.v), dir = trueBearing(r, &p, w.position, bearing(c.u, c.v));
            wp["current"] = {{"u", rounded(speed * std::sin(dir * M_PI / 180.0), 1e-4)},
                             {"v", rounded(speed * std::cos(dir * M_PI / 180.0), 1e-4)},
                             {"speed", rounded(speed, 1e-4)},
                             {"dir_deg", rounded(dir, 0.1)}};
        }
        else
            wp["current"] = nullptr;
        wps.push_back(std::move(wp));
    }
    route["waypoints"] = std::move(wps);
    return route;
}

/// The land of the field (cells sampled about 150 across the region whose centre is not water) and the keep-off
/// band (water within the pilot's distance of land), each as row runs of cells.
void landAndBand(const MissionProblem &p, const Frame &f, PageJson &land, PageJson &band)
{
    const Region &b = p.getBox();
    const double w = b.xMax - b.xMin, h = b.yMax - b.yMin;
    if (!(w > 0.0) || !(h > 0.0))
        return;
    const double cell = std::max(w, h) / 150.0;
    const int nx = std::max(1, static_cast<int>(std::ceil(w / cell))),
              ny = std::max(1, static_cast<int>(std::ceil(h / cell)));
    const CurrentField &field = *p.getField();
    const FieldGrid *grid = field.grid();
    const KeepOffZone *keep = p.getLand() && p.getLand()->distance() > 0.0 ? p.getLand().get() : nullptr;
    const double z = p.getSpec().vehicle.depth, dx = w / nx, dy = h / ny;
    auto rect = [&](int i0, int i1, int j) {
        const double x0 = b.xMin + i0 * dx, x1 = b.xMin + i1 * dx, y0 = b.yMin + j * dy, y1 = y0 + dy;
        return f.line(std::vector<Point2>{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}});
    };
    for (int j = 0; j < ny; ++j)
    {
        int runStart[2] = {-1, -1};
        for (int i = 0; i <= nx; ++i)
        {
            int kind = -1; // 0 land, 1 keep-off band
            if (i < nx)
            {
                const double x = b.xMin + (i + 0.5) * dx, y = b.yMin + (j + 0.5) * dy;
                if (!field.inWater(x, y, z))
                    kind = !grid || grid->covers(x, y) ? 0 : -1; // outside a forecast's grid: no data, not land
                else if (keep && keep->distanceTo(x, y) < keep->distance())
                    kind = 1;
            }
            for (int k = 0; k < 2; ++k)
                if (kind != k && runStart[k] >= 0)
                {
                    (k == 0 ? land : band).push_back(rect(runStart[k], i, j));
                    runStart[k] = -1;
                }
                else if (kind == k && runStart[k] < 0)
                    runStart[k] = i;
        }
    }
}

/// The current as arrows at six times from the departure to the arrival, on a grid regular in the map's
/// coordinates (lon/lat, or the frame's) of about 24 across @p bounds ([[south, west], [north, east]]), so that the
/// page can thin it by index when zoomed out.
PageJson currentsJson(const MissionResult &r, const MissionProblem &p, const Frame &f, const PageJson &bounds)
{
    const Region &b = p.getBox();
    const CurrentField &field = *p.getField();
    const MissionSpec &m = r.spec;
    const double w = b.xMax - b.xMin, h = b.yMax - b.yMin;
    PageJson out{{"units", m.current.isForecast() ? "m/s" : ""}, {"frames", PageJson::array()}};
    if (!(w > 0.0) || !(h > 0.0))
        return out;
    const double t0 = r.plan.departure;
    const double s0 = bounds[0][0].get<double>(), w0 = bounds[0][1].get<double>(), n1 = bounds[1][0].get<double>(),
                 e1 = bounds[1][1].get<double>();
    const double step = std::max(n1 - s0, e1 - w0) / 24.0;
    double span = r.plan.solved ? r.plan.travelTime : m.planner.horizon;
    span = std::min(span, field.timeEnd() - t0);
    if (!std::isfinite(span) || span < 0.0)
        span = 0.0;
    const int frames = span > 0.0 ? 6 : 1;
    const double z = m.vehicle.depth;
    double vmax = 0.0;
    for (int k = 0; k < frames; ++k)
    {
        const double t = t0 + (frames > 1 ? span * k / (frames - 1) : 0.0);
        PageJson arrows = PageJson::array();
        for (int j = 0; s0 + (j + 0.5) * step < n1; ++j)
            for (int i = 0; w0 + (i + 0.5) * step < e1; ++i)
            {
                const double a = s0 + (j + 0.5) * step, o = w0 + (i + 0.5) * step; // map coordinates
                const Point2 q = f.local(a, o);
                const double x = q.x, y = q.y;
                if (!(x >= b.xMin && x <= b.xMax && y >= b.yMin && y <= b.yMax) || !field.inWater(x, y, z))
                    continue;
                const Velocity c = field.velocity(x, y, z, t);
                if (!std::isfinite(c.u) || !std::isfinite(c.v))
                    continue;
                vmax = std::max(vmax, std::hypot(c.u, c.v));
                arrows.push_back(
                    PageJson::array({rounded(a, 1e-6), rounded(o, 1e-6), rounded(c.u, 1e-4), rounded(c.v, 1e-4)}));
            }
        out["frames"].push_back({{"time", pageTime(p, t)}, {"arrows", std::move(arrows)}});
    }
    out["max_speed"] = vmax;
    return out;
}

PageJson isochronesJson(const MissionResult &r, const MissionProblem &p, const Frame &f)
{
    PageJson out = PageJson::array();
    if (!r.isochrones)
        return out;
    for (const Isochrone &c : r.isochrones->contours)
    {
        PageJson lines = PageJson::array();
        for (const auto &l : c.lines)
            lines.push_back(f.line(l));
        out.push_back({{"time", c.iso.empty() ? pageTime(p, c.time) : c.iso}, {"lines", std::move(lines)}});
    }
    return out;
}

/// The probability of reach for the page ([SubramaniStochastic]): per frame its date and p on the grid as percents
/// (rows from the north, at most 160 cells a side: every s-th node), drawn as an image between the grid's corners,
/// and its contours per level. Null without it.
PageJson reachabilityPageJson(const MissionResult &r, const MissionProblem &p, const Frame &f)
{
    if (!r.reachability || r.reachability->probability.empty())
        return nullptr;
    const ReachProbability &rp = *r.reachability;
    const int s = std::max(1, static_cast<int>(std::ceil(std::max(rp.nx, rp.ny) / 160.0)));
    const int nx = (rp.nx - 1) / s + 1, ny = (rp.ny - 1) / s + 1;
    const double half = 0.5 * s * rp.h;
    const double xMax = rp.x0 + (nx - 1) * s * rp.h, yMax = rp.y0 + (ny - 1) * s * rp.h;
    PageJson frames = PageJson::array();
    for (std::size_t k = 0; k < rp.times.size(); ++k)
    {
        PageJson values = PageJson::array();
        for (int j = ny - 1; j >= 0; --j)
            for (int i = 0; i < nx; ++i)
                values.push_back(static_cast<int>(std::lround(
                    100.0 *
                    rp.probability[k][static_cast<std::size_t>(j * s) * rp.nx + static_cast<std::size_t>(i * s)])));
        PageJson contours = PageJson::array();
        for (const double level : rp.levels)
        {
            PageJson lines = PageJson::array();
            for (const ReachContour &c : rp.contours)
                if (c.time == rp.times[k] && c.level == level)
                    for (const auto &l : c.lines)
                        lines.push_back(f.line(l));
            contours.push_back(std::move(lines));
        }
        frames.push_back({{"time", pageTime(p, rp.times[k])},
                          {"since", elapsedText(r.spec, rp.times[k] - rp.departure)},
                          {"p", std::move(values)},
                          {"contours", std::move(contours)}});
    }
    std::string goal = "goal by the horizon: p = " + text::number(rp.goalProbability, 3);
    for (const ReachQuantile &q : rp.quantiles)
        goal += ", " + text::number(100.0 * q.q, 3) + " %: " +
                (q.reached ? (q.iso.empty() ? pageTime(p, q.arrival) : q.iso) : std::string("not by the horizon"));
    return {{"members", rp.members},
            {"levels", rp.levels},
            {"grid",
             {{"nx", nx},
              {"ny", ny},
              {"sw", f.at({rp.x0 - half, rp.y0 - half})},
              {"ne", f.at({xMax + half, yMax + half})}}},
            {"frames", std::move(frames)},
            {"goal", goal}};
}

PageJson tracksJson(const MissionResult &r, const Frame &f)
{
    PageJson out = PageJson::array();
    if (!r.execution || r.execution->runs.empty() || !r.execution->runs.front().planned)
        return out;
    const ExecutionResult &e = *r.execution;
    for (std::size_t k = 0; k < e.strategies.size() && k < e.runs.front().flown.size(); ++k)
        out.push_back({{"name", "flown (" + controlStrategyName(e.strategies[k]) + ")"},
                       {"points", f.line(e.runs.front().flown[k].fixes)}});
    return out;
}

/// The glider's history with observations: its past fixes and the DAC it measured (lon/lat), and the arrows' scale:
/// the fastest DAC drawn a twelfth of the region's height long. Null without observations.
PageJson gliderJson(const MissionProblem &p)
{
#if OMPL_GLIDER_WITH_NETCDF
    const auto &o = p.observations();
    if (!o || !p.isGeographic())
        return nullptr;
    PageJson fixes = PageJson::array(), dac = PageJson::array();
    for (const GliderFix &g : surfacingFixes(*o)) // the DAC's positions (mid-dive) are drawn as the DAC
        fixes.push_back({{"lat", g.at.lat}, {"lon", g.at.lon}, {"time", formatIsoTime(g.time)}});
    double fastest = 0.0;
    for (const DacRecord &d : o->dac)
    {
        dac.push_back({{"lat", d.at.lat}, {"lon", d.at.lon}, {"u", d.u}, {"v", d.v}, {"time", formatIsoTime(d.time)}});
        fastest = std::max(fastest, std::hypot(d.u, d.v));
    }
    const Region &b = p.getBox();
    const double height = std::abs(p.toGeographic({0.5 * (b.xMin + b.xMax), b.yMax}).lat -
                                   p.toGeographic({0.5 * (b.xMin + b.xMax), b.yMin}).lat);
    return {{"fixes", fixes}, {"dac", dac}, {"arrow_deg_per_ms", fastest > 0.0 ? height / 12.0 / fastest : 0.05}};
#else
    (void)p;
    return nullptr;
#endif
}

/// JSON as a <script> may hold it: '<' written \u003c (no "</script" nor "<!--"), U+2028/U+2029 escaped.
std::string scriptSafe(const std::string &s)
{
    std::string out;
    out.reserve(s.size());
    for (std::size_t i = 0; i < s.size(); ++i)
    {
        if (s[i] == '<')
            out += "\\u003c";
        else if (s.compare(i, 3, "\xE2\x80\xA8") == 0 || s.compare(i, 3, "\xE2\x80\xA9") == 0)
        {
            out += s[i + 2] == '\xA8' ? "\\u2028" : "\\u2029";
            i += 2;
        }
        else
            out += s[i];
    }
    return out;
}
} // namespace

std::string mapHtmlData(const MissionResult &r, const MissionProblem &p)
{
    const Frame f(p);
    const MissionSpec &m = r.spec;
    PageJson d;
    d["title"] = m.name;
    d["geographic"] = f.geographic();
    d["units"] = f.units();
    d["routes"] = PageJson::array({routeJson(r, p, f)});
    const Point2 s = p.getStart(), g = p.getGoal();
    d["start"] = f.at(s);
    d["goal"] = f.at(g);
    d["goal_tolerance"] = f.length(m.planner.goalTolerance);
    // a mission's via points: position, radius, arrival (a date where the field has dates) and stay
    PageJson stations = PageJson::array();
    for (std::size_t i = 0; i < p.getViaPoints().size(); ++i)
    {
        const ViaPointSpec &v = m.waypoints[i];
        PageJson st{{"name", v.name},
                    {"at", f.at(p.getViaPoints()[i])},
                    {"radius", std::isfinite(v.radius) ? PageJson(f.length(v.radius)) : PageJson(nullptr)},
                    {"stay", v.stay > 0.0 ? PageJson(v.stay) : PageJson(nullptr)},
                    {"arrival", nullptr}};
        for (const PlannedLeg &l : r.legs)
            if (l.toVia == static_cast<int>(i) && l.plan.solved)
            {
                const std::string iso = p.isoTime(l.arrival());
                st["arrival"] = iso.empty() ? PageJson(l.arrival()) : PageJson(iso);
            }
        stations.push_back(st);
    }
    d["stations"] = stations;
    d["isochrones"] = isochronesJson(r, p, f);
    PageJson land = PageJson::array(), band = PageJson::array(), coast = PageJson::array(),
             forbidden = PageJson::array();
    landAndBand(p, f, land, band);
    for (const MissionPolygon &poly : p.getPolygons())
    {
        if (poly.coastline)
            coast.push_back(f.line(poly.points));
        else if (poly.kind == RegionKind::Island || poly.kind == RegionKind::Land)
            land.push_back(f.line(poly.points));
        else
        {
            PageJson windows =
                PageJson::array(); // a closure's: when it is closed (as dates where the mission has them)
            for (const auto &[from, to] : poly.windows)
            {
                const std::string a = p.isoTime(from), b = p.isoTime(to);
                windows.push_back({a.empty() ? PageJson(from) : PageJson(a), b.empty() ? PageJson(to) : PageJson(b)});
            }
            forbidden.push_back({{"name", poly.name + " (" + regionKindName(poly.kind) + ")"},
                                 {"windows", windows},
                                 {"rings", PageJson::array({f.line(poly.points)})}});
        }
    }
    for (auto &ring : coast)
        land.push_back(ring); // a coastline's land, filled
    d["land"] = std::move(land);
    d["coastlines"] = std::move(coast);
    d["keep_off"] = std::move(band);
    d["forbidden"] = std::move(forbidden);
    d["tracks"] = tracksJson(r, f);
    d["reachability"] = reachabilityPageJson(r, p, f);
    d["glider"] = gliderJson(p);
    const Region &b = p.getBox();
    PageJson lo = f.at({b.xMin, b.yMin}), hi = f.at({b.xMax, b.yMax});
    for (const Point2 q : {Point2{b.xMin, b.yMax}, Point2{b.xMax, b.yMin}, Point2{0.5 * (b.xMin + b.xMax), b.yMin},
                           Point2{0.5 * (b.xMin + b.xMax), b.yMax}})
    {
        const PageJson c = f.at(q);
        lo = PageJson::array(
            {std::min(lo[0].get<double>(), c[0].get<double>()), std::min(lo[1].get<double>(), c[1].get<double>())});
        hi = PageJson::array(
            {std::max(hi[0].get<double>(), c[0].get<double>()), std::max(hi[1].get<double>(), c[1].get<double>())});
    }
    d["bounds"] = PageJson::array({lo, hi});
    d["currents"] = currentsJson(r, p, f, d["bounds"]);
    return output_json::utf8Dump(d);
}

std::string mapHtmlPage(const std::vector<std::string> &data, const std::string &title)
{
    if (data.empty())
        throw Error("map.html: no plan to draw");
    PageJson d = PageJson::parse(data.front(), nullptr, false);
    if (d.is_discarded() || !d.is_object() || !d.contains("routes"))
        throw Error("map.html: the map data is not what mapHtmlData() writes");
    for (std::size_t k = 1; k < data.size(); ++k)
    {
        const PageJson more = PageJson::parse(data[k], nullptr, false);
        if (more.is_discarded() || !more.is_object() || !more.contains("routes"))
            throw Error("map.html: the map data is not what mapHtmlData() writes");
        for (const PageJson &route : more["routes"])
            d["routes"].push_back(route);
        for (const char *key : {"isochrones", "tracks"})
            if (more.contains(key))
                for (const PageJson &x : more[key])
                    d[key].push_back(x);
    }
    d["title"] = title;
    // the template's three places, found first and filled in one pass (a placeholder-like text in what is put in
    // is never looked at again); Leaflet is put in as Debian ships it (a "</script" in it would end the element)
    const std::string page = joined(maphtml::kTemplate);
    std::string js = joined(maphtml::kLeafletJs);
    for (std::size_t at = js.find("</script"); at != std::string::npos; at = js.find("</script", at + 2))
        js.replace(at, 2, "<\\/");
    const std::pair<const char *, std::string> parts[] = {{"/*LEAFLET_CSS*/", joined(maphtml::kLeafletCss)},
                                                          {"/*LEAFLET_JS*/", js},
                                                          {"/*MAP_DATA*/", scriptSafe(output_json::utf8Dump(d))}};
    std::vector<std::pair<std::size_t, const std::pair<const char *, std::string> *>> at;
    for (const auto &part : parts)
    {
        const std::size_t k = page.find(part.first);
        if (k == std::string::npos || page.find(part.first, k + 1) != std::string::npos)
            throw Error(std::string("map.html: the page template must hold ") + part.first + " once");
        at.push_back({k, &part});
    }
    std::sort(at.begin(), at.end());
    std::string out;
    std::size_t from = 0;
    for (const auto &[k, part] : at)
    {
        out.append(page, from, k - from);
        out += part->second;
        from = k + std::string(part->first).size();
    }
    out.append(page, from, std::string::npos);
    return out;
}

std::string mapHtmlDataOf(const std::string &page)
{
    const std::string begin = "window.GLIDER_MAP = ";
    const std::size_t a = page.find(begin);
    const std::size_t b = a == std::string::npos ? a : page.find(";\n", a);
    if (b == std::string::npos)
        return "";
    const PageJson d = PageJson::parse(page.substr(a + begin.size(), b - a - begin.size()), nullptr, false);
    return d.is_discarded() || !d.is_object() || !d.contains("routes") ? std::string() : output_json::utf8Dump(d);
}

std::string mapHtml(const MissionResult &r, const MissionProblem &p)
{
    return mapHtmlPage({mapHtmlData(r, p)}, r.spec.name);
}
} // namespace ompl_glider
