#pragma once
/// @file MissionReader.h
/// @brief Internal to the mission loader: the YAML reader that names file:line and the dotted field in every error,
/// and the readers of the mission's sections (one per top-level key). Not installed.
#include <yaml-cpp/yaml.h>

#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "ompl_glider/mission/MissionSpec.h"

namespace ompl_glider::mission_loader
{
/// @p p relative to the mission file's directory @p dir (absolute paths unchanged).
std::string joinPath(const std::string &dir, const std::string &p);
bool fileExists(const std::string &p);
/// The message for a YAML parse failure of @p file: "file:line: <what>: <yaml-cpp's message>", or that the text is
/// nested too deeply (yaml-cpp stops at 500 levels with a misleading "bad file").
std::string yamlErrorMessage(const std::string &file, const YAML::ParserException &e, const std::string &what);

/// Reads one mission; every accessor names the file, the line and the dotted field.
class Reader
{
public:
    Reader(std::string file, std::string dir) : file_(std::move(file)), dir_(std::move(dir)) {}

    const std::string &file() const { return file_; }
    const std::string &dir() const { return dir_; }

    [[noreturn]] void fail(const YAML::Node &node, const std::string &field, const std::string &what) const;
    [[noreturn]] void failAt(int line, const std::string &field, const std::string &what) const;
    /// "file:line: " of @p node ("file: " when the node has no position).
    std::string where(const YAML::Node &node) const;
    int line(const YAML::Node &node) const { return node.Mark().line + 1; }
    static std::string sub(const std::string &path, const std::string &key)
    {
        return path.empty() ? key : path + "." + key;
    }

    /// The node must be a map whose keys are all in @p allowed.
    void checkMap(const YAML::Node &node, const std::string &path, const std::set<std::string> &allowed) const;
    double number(const YAML::Node &node, const std::string &field) const;
    double finite(const YAML::Node &node, const std::string &field) const;
    double positive(const YAML::Node &node, const std::string &field) const;
    double nonNegative(const YAML::Node &node, const std::string &field) const;
    long integer(const YAML::Node &node, const std::string &field, long lo, long hi) const;
    bool boolean(const YAML::Node &node, const std::string &field) const;
    std::string text(const YAML::Node &node, const std::string &field) const;
    std::string oneOf(const YAML::Node &node, const std::string &field, const std::set<std::string> &values) const;
    /// A time: a number in field units, or an ISO 8601 date converted with the mission's epoch or file calendar.
    double time(const YAML::Node &node, const std::string &field, const MissionSpec &m) const;
    /// A setting of the declared ranges (mission/SettingRanges.h): a number, or for a length or a duration a text
    /// with its unit, read and checked against the setting's row (@p field "waypoints[2].radius" is the row
    /// "waypoints[].radius").
    double setting(const YAML::Node &node, const std::string &field, const MissionSpec &m) const;
    /// A [a, b] pair of numbers.
    std::pair<double, double> pair(const YAML::Node &node, const std::string &field) const;
    /// A list of at least 3 pairs.
    std::vector<std::pair<double, double>> ring(const YAML::Node &node, const std::string &field) const;

    /// Where each value read so far was given (MissionSpec::marks).
    const std::map<std::string, SourceMark> &marks() const { return marks_; }
    /// Records where @p field was given, for a value read without the typed readers above (durations, lengths).
    void mark(const YAML::Node &node, const std::string &field) const { remember(node, field); }

private:
    void remember(const YAML::Node &node, const std::string &field) const
    {
        const auto key = keyLines_.find(field); // an empty value's own mark is the next token's
        marks_[field] = SourceMark{file_, node.IsNull() && key != keyLines_.end() ? key->second : line(node)};
    }

    std::string file_, dir_;
    mutable std::map<std::string, SourceMark> marks_;
    mutable std::map<std::string, int> keyLines_; // the line of each key checkMap() saw, by its dotted field
};

// Readers of the mission's parts; each validates its node and fills its part of @p m.
/// A point {x, y} or {lon, lat}; @p extraKeys are further keys the node may hold (read by the caller).
void readPoint(const Reader &r, const YAML::Node &n, const std::string &field, PointSpec &p, const MissionSpec &m,
               const std::set<std::string> &extraKeys = {});
/// A list of via points under @p field ("waypoints", "fleet[2].waypoints"): each {name, lon/lat or x/y, radius,
/// arrive: {begin, end}, stay}; names unique and plain (letters, digits, '_', '-'), after the departure.
void readViaPoints(const Reader &r, const YAML::Node &n, const std::string &field, std::vector<ViaPointSpec> &out,
                   const MissionSpec &m);
/// The `observations` section: a path, or {file, length_scale, time_scale, error_ratio}.
void readObservations(const Reader &r, const YAML::Node &n, MissionSpec &m);
/// The visiting order ("given" or "free") of @p field, checked against the number of via points @p count.
VisitOrder readVisitOrder(const Reader &r, const YAML::Node &n, const std::string &field, std::size_t count);
/// The optional key `threads` of @p n (path @p f + ".threads" in messages): an integer 0 .. 1024 into @p threads
/// when given (0: all cores); @p threads keeps its value otherwise.
void readThreads(const Reader &r, const YAML::Node &n, const std::string &f, unsigned &threads);
/// A duration: a number in field units, or a text "<number> s|min|h|d" converted with units.time_s.
double duration(const Reader &r, const YAML::Node &n, const std::string &f, const MissionSpec &m);
void readPolygon(const Reader &r, const YAML::Node &n, const std::string &field, PolygonSpec &poly,
                 const MissionSpec &m);
/// The `current` section @p n. With forecast runs, @p departure (the mission's `departure`, may be undefined) chooses
/// the mission's clock: a departure date given sets it to the first time of the newest run available then (the run
/// the plan is made on, read on its own clock as that file alone), else the earliest run's.
void readCurrent(const Reader &r, const YAML::Node &n, MissionSpec &m, const YAML::Node &departure = YAML::Node());
/// A current source (the `current` section's keys) under the dotted field @p field, without the file calendar;
/// @p extraKeys are further keys the node may hold (read by the caller).
void readCurrentSource(const Reader &r, const YAML::Node &n, const std::string &field, CurrentSpec &c,
                       const std::set<std::string> &extraKeys = {});
/// True when the `current` node @p n is the short form of a drawn ensemble (members, spread or seed given).
bool isDrawnEnsemble(const YAML::Node &n);
/// `current: {type, parameters, members: N, spread: {...}, seed: S}`: the members drawn (drawEnsembleMembers())
/// into MissionSpec::current as a listed ensemble's, CurrentSpec::drawn set.
void readDrawnEnsemble(const Reader &r, const YAML::Node &n, MissionSpec &m);
void readExecution(const Reader &r, const YAML::Node &n, MissionSpec &m);
void readRegion(const Reader &r, const YAML::Node &n, MissionSpec &m);
void readDeparture(const Reader &r, const YAML::Node &n, MissionSpec &m);
/// The goal's arrival window `goal.window: {begin, end}` (times read as the departure's), after readDeparture().
void readGoalWindow(const Reader &r, const YAML::Node &n, MissionSpec &m);
void readDive(const Reader &r, const YAML::Node &n, MissionSpec &m);
void readForbidden(const Reader &r, const YAML::Node &n, MissionSpec &m);
/// The `safety` section (keep_off, bathymetry, bathymetry_variable, min_depth), after the current.
void readSafety(const Reader &r, const YAML::Node &n, MissionSpec &m);
void readPlanner(const Reader &r, const YAML::Node &n, MissionSpec &m);
void readStints(const Reader &r, const YAML::Node &n, MissionSpec &m);
void readOutputs(const Reader &r, const YAML::Node &n, MissionSpec &m);
/// The `reachability` section (horizon, interval, levels, quantiles, resolution, member_arrival).
void readReachability(const Reader &r, const YAML::Node &n, MissionSpec &m);
/// The `fleet` list (name, start, goal, speed, departure per glider), after the departure and the region.
void readFleet(const Reader &r, const YAML::Node &n, MissionSpec &m);
} // namespace ompl_glider::mission_loader
