// A Slocum glider's binary files (SlocumBinary.h), written by the test from the format's public description
// (SlocumBinaryWriter.h): the decoder gives back every value written, in both byte orders, from the compressed files,
// with the sensor list in the file or in a cache file (beside the files, in cache/ beside them, in a folder given);
// bad files are refused naming the file and what is wrong. As observations, the binary files give the DAC and fixes
// of their dba twins to the bit, and the same plan; the dba files plan as the IOOS files of the same deployment.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "RealtimeDeployment.h"
#include "SlocumBinaryWriter.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/io/GliderObservations.h"
#include "ompl_glider/io/SlocumBinary.h"
#include "ompl_glider/io/Time.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/MissionSpec.h"
#include "ompl_glider/mission/Overrides.h"
#include "ompl_glider/mission/Planning.h"

using namespace ompl_glider;
using namespace realtime_test;
namespace fs = std::filesystem;

namespace
{
/// The sensors of the tests' binary files: those of the dba files (kSensors) in the sizes a glider writes them, an
/// int16 one, and one listed but not in the file.
const std::vector<slocum_test::Sensor> kBinarySensors = {{"m_present_time", "timestamp", 8},
                                                         {"sci_water_temp", "degc", 4, false},
                                                         {"m_gps_lat", "lat", 8},
                                                         {"m_gps_lon", "lon", 8},
                                                         {"m_gps_status", "enum", 1},
                                                         {"m_water_vx", "m/s", 8},
                                                         {"m_water_vy", "m/s", 8},
                                                         {"m_depth", "m", 4},
                                                         {"m_num_half_yos_in_segment", "nodim", 2}};

/// Degrees as the Slocum's [-]DDMM.MMMM number (the placeholder and NaN as they are).
double degMin(double x)
{
    if (std::isnan(x) || x == 69696969.0)
        return x;
    const double a = std::abs(x), deg = std::floor(a), v = 100.0 * deg + (a - deg) * 60.0;
    return x < 0 ? -v : v;
}

/// The cycles of @p rows in kBinarySensors' file order (the int16 sensor counting the rows).
std::vector<std::vector<double>> cyclesOf(const std::vector<SlocumRow> &rows)
{
    std::vector<std::vector<double>> out;
    for (std::size_t i = 0; i < rows.size(); ++i)
    {
        const SlocumRow &r = rows[i];
        out.push_back({r.time, degMin(r.lat), degMin(r.lon), r.status, r.vx, r.vy, r.depth,
                       i % 3 == 0 ? -300.0 + static_cast<double>(i) : NAN});
    }
    return out;
}

void writeBytes(const fs::path &p, const std::string &bytes)
{
    std::ofstream(p, std::ios::binary) << bytes;
}

/// The deployment of the dba tests (slocumRows()) as binary files in @p dir: the first file big-endian, the second
/// little-endian; @p compressed: as .scd files.
void writeBinary(const fs::path &dir, const std::vector<Surfacing> &d, bool compressed = false,
                 slocum_test::Options o = {})
{
    const auto rows = slocumRows(d);
    for (int f = 0; f < 2; ++f)
    {
        o.bigEndian = f == 0;
        const std::string raw = slocum_test::encode(kSlocumFiles[f], kBinarySensors, cyclesOf(rows[f]), o);
        writeBytes(dir / (std::string(kSlocumFiles[f]) + (compressed ? ".scd" : ".sbd")),
                   compressed ? slocum_test::compress(raw) : raw);
    }
}

std::string binaryErrorOf(const std::string &file, const std::string &cache = "")
{
    try
    {
        readSlocumBinary(file, {}, cache);
    }
    catch (const Error &e)
    {
        return e.what();
    }
    return "";
}

std::vector<Surfacing> surfacings()
{
    return since(deployment(), parseIsoTime(kSince));
}

/// Equal values, NaN equal to NaN.
void expectSameValue(double a, double b, const std::string &where)
{
    if (std::isnan(b))
        EXPECT_TRUE(std::isnan(a)) << where << ": " << a;
    else
        EXPECT_EQ(a, b) << where;
}

/// The same observations to the bit: DAC with their segments and depths, fixes, last fix, counts.
void expectSameObservations(const GliderObservations &a, const GliderObservations &b)
{
    ASSERT_EQ(a.dac.size(), b.dac.size());
    for (std::size_t i = 0; i < a.dac.size(); ++i)
    {
        const DacRecord &x = a.dac[i], &y = b.dac[i];
        for (const auto &[p, q, what] : {std::tuple{x.time, y.time, "time"},
                                         {x.at.lon, y.at.lon, "lon"},
                                         {x.at.lat, y.at.lat, "lat"},
                                         {x.u, y.u, "u"},
                                         {x.v, y.v, "v"},
                                         {x.segmentStart, y.segmentStart, "segmentStart"},
                                         {x.segmentEnd, y.segmentEnd, "segmentEnd"},
                                         {x.depthMin, y.depthMin, "depthMin"},
                                         {x.depthMax, y.depthMax, "depthMax"}})
            expectSameValue(p, q, std::string(what) + " " + std::to_string(i));
    }
    ASSERT_EQ(a.fixes.size(), b.fixes.size());
    for (std::size_t i = 0; i < a.fixes.size(); ++i)
    {
        EXPECT_EQ(a.fixes[i].time, b.fixes[i].time) << i;
        EXPECT_EQ(a.fixes[i].at.lon, b.fixes[i].at.lon) << i;
        EXPECT_EQ(a.fixes[i].at.lat, b.fixes[i].at.lat) << i;
    }
    ASSERT_TRUE(a.lastFix && b.lastFix);
    EXPECT_EQ(a.lastFix->time, b.lastFix->time);
    EXPECT_EQ(a.rejected, b.rejected);
    EXPECT_EQ(a.notes, b.notes);
    EXPECT_EQ(a.platform, b.platform);
    expectSameValue(a.newestSurfacing, b.newestSurfacing, "newestSurfacing");
}

/// The plan from the observations' last fix on the example forecast to a goal 4 km away (as glider_plan's
/// --observations with --no-refine --no-global-check).
MissionResult planWith(const std::string &observations)
{
    return runMission(MissionProblem(
        parseMission(std::string("name: obs\ncurrent: {type: netcdf, file: '") + OMPL_GLIDER_SOURCE_DIR +
                         "/examples/labrador_forecast.nc'}\ngoal: {lon: -52.33, lat: 48.07}\nvehicle: {speed: 0.3}\n"
                         "planner: {refinement: false, global_check: false}\nobservations: '" +
                         observations + "'\n",
                     "obs.yaml")));
}

/// Two plans within @p tolerance: travel time (relative) and every point of the path (s, and planning units
/// relative to the path's extent).
void expectSamePlan(const MissionResult &a, const MissionResult &b, double tolerance)
{
    ASSERT_TRUE(a.plan.solved && b.plan.solved);
    EXPECT_NEAR(a.plan.travelTime, b.plan.travelTime, tolerance * b.plan.travelTime);
    ASSERT_EQ(a.plan.path.size(), b.plan.path.size());
    for (std::size_t i = 0; i < a.plan.path.size(); ++i)
    {
        EXPECT_NEAR(a.plan.path[i].t, b.plan.path[i].t, tolerance * b.plan.travelTime) << i;
        EXPECT_NEAR(a.plan.path[i].x, b.plan.path[i].x, tolerance * 1e4) << i;
        EXPECT_NEAR(a.plan.path[i].y, b.plan.path[i].y, tolerance * 1e4) << i;
    }
}
} // namespace

TEST(SlocumBinary, DecoderGivesBackEveryValueInBothByteOrders)
{
    const fs::path d = freshDir("slocum_roundtrip");
    const auto rows = slocumRows(surfacings());
    const std::vector<std::vector<double>> cycles = cyclesOf(rows[0]);
    for (const bool big : {true, false})
    {
        SCOPED_TRACE(big ? "big-endian" : "little-endian");
        slocum_test::Options o;
        o.bigEndian = big;
        const fs::path file = d / (big ? "ru29-2026-074-0-0.sbd" : "ru29-2026-074-0-0.dbd");
        writeBytes(file, slocum_test::encode("ru29-2026-074-0-0", kBinarySensors, cycles, o));
        const SlocumBinaryData got = readSlocumBinary(file.string());
        EXPECT_EQ(got.bigEndian, big);
        EXPECT_FALSE(got.compressed);
        EXPECT_EQ(got.sensorList, file.string());
        EXPECT_EQ(got.header.at("full_filename"), "ru29-2026-074-0-0");
        // the sensors in the file, in its order (the one marked F left out)
        ASSERT_EQ(got.sensors.size(), kBinarySensors.size() - 1);
        for (std::size_t k = 0, j = 0; k < kBinarySensors.size(); ++k)
            if (kBinarySensors[k].inFile)
            {
                EXPECT_EQ(got.sensors[j].name, kBinarySensors[k].name);
                EXPECT_EQ(got.sensors[j].units, kBinarySensors[k].units);
                EXPECT_EQ(got.sensors[j++].bytes, kBinarySensors[k].bytes);
            }
        ASSERT_EQ(got.cycles.size(), cycles.size());
        for (std::size_t i = 0; i < cycles.size(); ++i)
            for (std::size_t k = 0; k < cycles[i].size(); ++k)
            {
                // a float sensor gives the float of the value written; a repeated value (state 1) the value
                const double want = got.sensors[k].bytes == 4 ? static_cast<float>(cycles[i][k]) : cycles[i][k];
                expectSameValue(got.cycles[i][k], want, std::to_string(i) + " " + got.sensors[k].name);
            }
        // the sensors asked for, in the order asked; one the file has not left out
        const SlocumBinaryData some = readSlocumBinary(file.string(), {"m_water_vy", "nope", "m_present_time"});
        ASSERT_EQ(some.columns.size(), 2u);
        EXPECT_EQ(some.sensors[some.columns[0]].name, "m_water_vy");
        for (std::size_t i = 0; i < cycles.size(); ++i)
        {
            expectSameValue(some.cycles[i][0], cycles[i][5], "vy " + std::to_string(i));
            EXPECT_EQ(some.cycles[i][1], cycles[i][0]);
        }
    }
}

TEST(SlocumBinary, CompressedFilesAndCacheFilesAreReadAsTheUncompressed)
{
    const fs::path d = freshDir("slocum_compressed");
    const auto rows = slocumRows(surfacings());
    const std::string raw = slocum_test::encode("ru29-2026-074-0-1", kBinarySensors, cyclesOf(rows[1]));
    writeBytes(d / "plain.sbd", raw);
    const SlocumBinaryData plain = readSlocumBinary((d / "plain.sbd").string());
    for (const std::size_t chunk : {64u, 1000u, 20000u})
    {
        writeBytes(d / "packed.scd", slocum_test::compress(raw, chunk));
        EXPECT_EQ(decompressSlocumLz4(slocum_test::compress(raw, chunk), "x"), raw) << chunk;
        const SlocumBinaryData packed = readSlocumBinary((d / "packed.scd").string());
        EXPECT_TRUE(packed.compressed);
        ASSERT_EQ(packed.cycles.size(), plain.cycles.size());
        for (std::size_t i = 0; i < plain.cycles.size(); ++i)
            for (std::size_t k = 0; k < plain.cycles[i].size(); ++k)
                expectSameValue(packed.cycles[i][k], plain.cycles[i][k], std::to_string(i));
    }
    // the sensor list factored out: the cache file beside the file, in cache/ beside it, in a folder given, or
    // compressed (.ccc); each gives the same cycles
    slocum_test::Options o;
    o.factored = true;
    writeBytes(d / "factored.tbd", slocum_test::encode("ru29-2026-074-0-1", kBinarySensors, cyclesOf(rows[1]), o));
    const std::string list = slocum_test::sensorList(kBinarySensors);
    const fs::path other = freshDir("slocum_cache_given");
    const auto readWith = [&](const fs::path &cacheFile, const std::string &cacheDir, const std::string &bytes) {
        fs::create_directories(cacheFile.parent_path());
        writeBytes(cacheFile, bytes);
        const SlocumBinaryData got = readSlocumBinary((d / "factored.tbd").string(), {}, cacheDir);
        EXPECT_EQ(got.sensorList, cacheFile.string());
        ASSERT_EQ(got.cycles.size(), plain.cycles.size());
        for (std::size_t i = 0; i < plain.cycles.size(); ++i)
            for (std::size_t k = 0; k < plain.cycles[i].size(); ++k)
                expectSameValue(got.cycles[i][k], plain.cycles[i][k], cacheFile.string());
        fs::remove(cacheFile);
    };
    readWith(d / "1a2b3c4d.cac", "", list);
    readWith(d / "cache" / "1a2b3c4d.cac", "", list);
    readWith(other / "1a2b3c4d.cac", other.string(), list);
    readWith(d / "cache" / "1a2b3c4d.ccc", "", slocum_test::compress(list, 300));
    // none: refused naming the file, the cache file and the folders searched
    const std::string e = binaryErrorOf((d / "factored.tbd").string());
    EXPECT_NE(e.find((d / "factored.tbd").string() +
                     ": the sensor list is in the cache file '1a2b3c4d.cac' "
                     "(sensor_list_factored: 1), found in none of the folders " +
                     d.string() + ", " + (d / "cache").string()),
              std::string::npos)
        << e;
    // a cache file of another sensor list
    writeBytes(d / "1a2b3c4d.cac", slocum_test::sensorList({{"m_present_time", "timestamp", 8}}));
    EXPECT_NE(binaryErrorOf((d / "factored.tbd").string()).find("total_num_sensors says 9"), std::string::npos)
        << binaryErrorOf((d / "factored.tbd").string());
}

TEST(SlocumBinary, BadFilesAreRefusedNamingTheFileAndWhatIsWrong)
{
    const fs::path d = freshDir("slocum_bad");
    const auto rows = slocumRows(surfacings());
    const std::string raw = slocum_test::encode("ru29-2026-074-0-0", kBinarySensors, cyclesOf(rows[0]));
    const std::string f = (d / "bad.sbd").string();
    const auto check = [&](const std::string &bytes, const std::string &words) {
        writeBytes(f, bytes);
        const std::string e = binaryErrorOf(f);
        EXPECT_EQ(e.rfind(f + ":", 0), 0u) << e;
        EXPECT_NE(e.find(words), std::string::npos) << words << "\n" << e;
        // and through the observations' reader
        try
        {
            readGliderObservations(f);
            ADD_FAILURE() << "no error for " << words;
        }
        catch (const Error &x)
        {
            EXPECT_NE(std::string(x.what()).find(f), std::string::npos) << x.what();
        }
    };
    const std::size_t known = raw.find("sa\x12\x34");
    ASSERT_NE(known, std::string::npos);
    // truncated: in the header, in the sensor list, in the known bytes, inside a cycle, before the end tag
    check(raw.substr(0, 100), ":5: the file ends in its header");
    check(raw.substr(0, known - 30), "the sensor list ends after 8 sensors (total_num_sensors says 9)");
    check(raw.substr(0, known + 10), " byte " + std::to_string(known) + ": the file ends before its known bytes");
    check(raw.substr(0, known + 16 + 20), "the file ends inside a cycle");
    check(raw.substr(0, raw.size() - 1), " byte " + std::to_string(raw.size() - 1) +
                                             ": the file ends without its end "
                                             "tag 'X'");
    // an unknown encoding version
    std::string v = raw;
    v.replace(v.find("encoding_ver: 5"), 15, "encoding_ver: 7");
    check(v, " unknown encoding version 7 (encoding_ver; this reader knows 1 to 5)");
    // bad known bytes: the float's, the int16 in neither order
    std::string k = raw;
    k[known + 5] = static_cast<char>(k[known + 5] ^ 0x10);
    check(k, " byte " + std::to_string(known) + ": bad known bytes: the float 123.456 does not read as one");
    k = raw;
    k[known + 2] = 0x13;
    check(k, " byte " + std::to_string(known) + ": bad known bytes: the int16 0x1234 reads in neither byte order");
    // an unknown cycle tag
    std::string t = raw;
    t[known + 16] = 'q';
    check(t, " byte " + std::to_string(known + 16) + ": a cycle tag 'd' or the end tag 'X' expected, got 0x71");
    // a sensor line that is not one
    std::string s = raw;
    s.replace(s.find("s: T 2 1 8 m_gps_lat"), 20, "s: T 2 1 3 m_gps_lat");
    check(s, ":17: a sensor line 's: T|F <number> <index> <bytes 1, 2, 4 or 8> <name> <units>' expected");
    // compressed: a frame cut short, a corrupt block
    const std::string packed = slocum_test::compress(raw);
    writeBytes(d / "bad.scd", packed.substr(0, packed.size() - 5));
    EXPECT_NE(binaryErrorOf((d / "bad.scd").string()).find(": an LZ4 frame of"), std::string::npos)
        << binaryErrorOf((d / "bad.scd").string());
    std::string corrupt = packed;
    for (std::size_t i = 2; i < 40; ++i)
        corrupt[i] = static_cast<char>(0xff);
    writeBytes(d / "bad.scd", corrupt);
    EXPECT_NE(binaryErrorOf((d / "bad.scd").string()).find((d / "bad.scd").string() + ": byte 0: a corrupt LZ4 block"),
              std::string::npos)
        << binaryErrorOf((d / "bad.scd").string());
}

TEST(SlocumBinary, BinaryFilesAreTheirDbaTwinsAndPlanAsThem)
{
    const std::vector<Surfacing> s = surfacings();
    const fs::path dba = freshDir("slocum_twin_dba"), sbd = freshDir("slocum_twin_sbd"),
                   scd = freshDir("slocum_twin_scd"), ioos = freshDir("slocum_twin_ioos");
    writeDba(dba, s);
    writeBinary(sbd, s);
    slocum_test::Options factored;
    factored.factored = true;
    writeBinary(scd, s, true, factored);
    fs::create_directories(scd / "cache");
    std::ofstream(scd / "cache" / "1a2b3c4d.cac") << slocum_test::sensorList(kBinarySensors);
    // a science file beside them: skipped, counted
    slocum_test::Options science;
    science.extension = "tbd";
    writeBytes(sbd / "ru29-2026-074-0-0.tbd",
               slocum_test::encode("ru29-2026-074-0-0", {{"sci_m_present_time", "timestamp", 8}},
                                   {{parseIsoTime(kSince)}}, science));
    writeIoos(ioos, s);
    const GliderObservations fromDba = readGliderObservations(dba.string());
    const GliderObservations fromSbd = readGliderObservations(sbd.string());
    const GliderObservations fromScd = readGliderObservations(scd.string());
    EXPECT_EQ(fromSbd.files, 3u);
    EXPECT_EQ(fromSbd.notes.at("files without the glider's fixes and DAC (science files: m_present_time, m_gps_lat, "
                               "m_water_vx, ... not in them)"),
              1u);
    GliderObservations sbdDacOnly = fromSbd;
    sbdDacOnly.notes.clear();
    expectSameObservations(sbdDacOnly, fromDba);
    expectSameObservations(fromScd, fromDba);
    ASSERT_EQ(fromDba.dac.size(), 4u);
    // the plans: binary as dba to 1e-9, dba as the IOOS files to 1e-6
    const MissionResult planDba = planWith(dba.string()), planIoos = planWith(ioos.string());
    expectSamePlan(planWith(sbd.string()), planDba, 1e-9);
    expectSamePlan(planWith(scd.string()), planDba, 1e-9);
    expectSamePlan(planDba, planIoos, 1e-6);
}

// A dockserver keeps the cache files in a folder of their own: the mission's observations.cache and the command
// line's --observations-cache (MissionOverrides) name it; without it the files' sensor lists are not found (exit 2,
// naming the cache file). Given, the plan is the one with the cache file beside the files.
TEST(SlocumBinary, ACacheFolderGivenByTheMissionOrTheFlagIsSearched)
{
    const std::vector<Surfacing> s = surfacings();
    const fs::path files = freshDir("slocum_cache_files"), cache = freshDir("slocum_cache_folder"),
                   beside = freshDir("slocum_cache_beside");
    slocum_test::Options factored;
    factored.factored = true;
    writeBinary(files, s, false, factored);
    writeBinary(beside, s, false, factored);
    std::ofstream(cache / "1a2b3c4d.cac") << slocum_test::sensorList(kBinarySensors);
    std::ofstream(beside / "1a2b3c4d.cac") << slocum_test::sensorList(kBinarySensors);
    // (the deployment's start, replaced by the last fix when the mission is made: a mission without a start reads
    // its last fix when it is loaded, before a flag can name the cache folder)
    const std::string mission = std::string("name: obs\ncurrent: {type: netcdf, file: '") + OMPL_GLIDER_SOURCE_DIR +
                                "/examples/labrador_forecast.nc'}\nstart: {lon: -52.6, lat: 47.95}\n"
                                "goal: {lon: -52.33, lat: 48.07}\n"
                                "vehicle: {speed: 0.3}\nplanner: {refinement: false, global_check: false}\n";
    const MissionResult reference =
        runMission(MissionProblem(parseMission(mission + "observations: '" + beside.string() + "'\n", "obs.yaml")));
    ASSERT_TRUE(reference.plan.solved);
    const MissionResult fromKey = runMission(MissionProblem(parseMission(
        mission + "observations: {file: '" + files.string() + "', cache: '" + cache.string() + "'}\n", "obs.yaml")));
    expectSamePlan(fromKey, reference, 1e-12);
    MissionSpec m = parseMission(mission + "observations: '" + files.string() + "'\n", "obs.yaml");
    try
    {
        MissionProblem p(m);
        ADD_FAILURE() << "the sensor list was found without its cache folder";
    }
    catch (const Error &e)
    {
        EXPECT_NE(std::string(e.what()).find("1a2b3c4d.cac"), std::string::npos) << e.what();
    }
    MissionOverrides o;
    o.origin = Origin::Flag;
    o.observationsCache = Given<std::string>{cache.string(), "--observations-cache"};
    applyOverrides(o, m);
    EXPECT_EQ(m.observations->cache, cache.string());
    expectSamePlan(runMission(MissionProblem(m)), reference, 1e-12);
}
