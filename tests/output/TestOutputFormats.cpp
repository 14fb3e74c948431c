// The output formats' writers (output/OutputFormatWriters.h): every format of outputFormats() has exactly one writer,
// each writer makes the files its format declares (OutputFormat::files) for a result to which every format applies,
// and outputFiles() puts them together: summary.json first, the formats in the table's order, the prefixed copies.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "ompl_glider/Config.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/MissionSpec.h"
#include "ompl_glider/mission/OutputFormats.h"
#include "ompl_glider/mission/Planning.h"
#include "ompl_glider/output/OutputFormatWriters.h"
#include "ompl_glider/output/OutputWriter.h"

using namespace ompl_glider;

namespace
{
std::vector<std::string> namesOf(const std::vector<OutputFile> &files)
{
    std::vector<std::string> names;
    for (const OutputFile &f : files)
        names.push_back(f.name);
    return names;
}

/// A geographic mission (a projection: the goto list and route.kml apply).
MissionSpec geographicMission()
{
    return parseMission(R"(name: formats
units: {length_m: 1000, time_s: 3600}
epoch: "2026-06-01T00:00:00Z"
projection: {lon0: -60.0, lat0: 40.0}
current: {type: uniform}
region: {x_min: -100, x_max: 100, y_min: -100, y_max: 100}
start: {x: 0, y: 0}
goal: {x: 1, y: 1}
)",
                        "formats.yaml");
}

/// A result of geographicMission() to which every format applies in full: a path, contours, stints, an execution
/// with a truth current. Nothing of it is written: only the files' names are asked.
MissionResult everyFormatResult(const MissionProblem &problem)
{
    MissionResult r;
    r.spec = problem.getSpec();
    r.plan.solved = true;
    r.isochrones.emplace();
    r.reachability.emplace();
    r.plan.stints.emplace();
    r.execution.emplace();
    r.spec.execution.enabled = true;
    r.spec.execution.truth = r.spec.current;
    r.spec.outputs.files.clear();
    for (const OutputFormat &format : outputFormats())
        r.spec.outputs.files.push_back(format.id);
    return r;
}
} // namespace

TEST(OutputFormats, EveryFormatHasExactlyOneWriter)
{
    for (const OutputFormat &format : outputFormats())
    {
        int rows = 0;
        for (const OutputFormatWriterRow &row : outputFormatWriters())
            rows += row.id == format.id;
        EXPECT_EQ(rows, 1) << "format '" << format.name << "'";
        EXPECT_NE(outputFormatWriter(format.id), nullptr) << format.name;
    }
    for (const OutputFormatWriterRow &row : outputFormatWriters())
    {
        int formats = 0;
        for (const OutputFormat &format : outputFormats())
            formats += format.id == row.id;
        EXPECT_EQ(formats, 1) << "writer of format " << static_cast<int>(row.id) << " has no row in outputFormats()";
        EXPECT_NE(row.writer, nullptr);
    }
    EXPECT_EQ(outputFormatWriters().size(), outputFormats().size());
}

TEST(OutputFormats, EachWriterMakesTheFilesItsFormatDeclares)
{
    const MissionProblem problem(geographicMission());
    ASSERT_TRUE(problem.isGeographic());
    const MissionResult r = everyFormatResult(problem);
    for (const OutputFormat &format : outputFormats())
    {
        const std::vector<std::string> declared = declaredFileNames(format, r.spec.outputs.gotoNumber);
        ASSERT_FALSE(declared.empty()) << format.name;
#if OMPL_GLIDER_WITH_MAP
        EXPECT_EQ(namesOf(outputFormatWriter(format.id)(r, problem, {"summary.json"})), declared)
            << "format '" << format.name << "' declares '" << format.files << "'";
#else
        if (format.id == OutputFormatId::Map)
            EXPECT_THROW(outputFormatWriter(format.id)(r, problem, {}), Error);
#endif
    }
}

TEST(OutputFormats, DeclaredNamesSplitTheListAndNameTheGotoFile)
{
    const OutputFormat format{OutputFormatId::Execution, "x", "a.csv, b.svg/png,goto_lNN.ma", "", false};
    EXPECT_EQ(declaredFileNames(format, 7), (std::vector<std::string>{"a.csv", "b.svg", "b.png", gotoFileName(7)}));
}

#if OMPL_GLIDER_WITH_MAP
TEST(OutputFormats, OutputFilesAreSummaryFirstThenTheFormatsInOrderThenThePrefixedCopies)
{
    const MissionProblem problem(geographicMission());
    MissionResult r = everyFormatResult(problem);
    r.spec.outputs.prefix = "run";
    std::vector<std::string> expected;
    for (const OutputFormat &format : outputFormats())
        for (const std::string &name : declaredFileNames(format, r.spec.outputs.gotoNumber))
            expected.push_back(name);
    ASSERT_EQ(expected.front(), "summary.json"); // the table's first row
    for (std::size_t i = 0, n = expected.size(); i < n; ++i)
        expected.push_back("run_" + expected[i]);
    EXPECT_EQ(namesOf(outputFiles(r, problem)), expected);

    // without a path the route's formats are left out, the others written
    r.plan.solved = false;
    r.spec.outputs.prefix.clear();
    std::vector<std::string> unrouted;
    for (const OutputFormat &format : outputFormats())
        if (!format.route)
            for (const std::string &name : declaredFileNames(format, r.spec.outputs.gotoNumber))
                unrouted.push_back(name);
    EXPECT_EQ(namesOf(outputFiles(r, problem)), unrouted);
}
#endif

TEST(OutputFormats, FormatsThatDoNotApplyMakeNoFiles)
{
    const MissionProblem problem(geographicMission());
    MissionResult r;
    r.spec = problem.getSpec();
    r.plan.solved = true;
    EXPECT_TRUE(outputFormatWriter(OutputFormatId::Isochrones)(r, problem, {}).empty()); // no contours
    EXPECT_TRUE(outputFormatWriter(OutputFormatId::Stints)(r, problem, {}).empty());     // no stints
    EXPECT_TRUE(outputFormatWriter(OutputFormatId::Execution)(r, problem, {}).empty());  // no execution
}
