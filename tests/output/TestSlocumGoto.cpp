// Tests of the Slocum goto list file (goto_lNN.ma) and its [-]DDDMM.MMMM coordinates.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <sstream>

#include "ompl_glider/Exception.h"
#include "ompl_glider/output/SlocumGoto.h"

using namespace ompl_glider;

TEST(SlocumGoto, DegMinFormatting)
{
    EXPECT_EQ(formatDegMin(-70.5), "-7030.0000");
    EXPECT_EQ(formatDegMin(41.25), "4115.0000");
    EXPECT_EQ(formatDegMin(-0.5), "-030.0000");
    EXPECT_EQ(formatDegMin(0.0), "000.0000");
    EXPECT_EQ(formatDegMin(5.123456), "507.4074");          // 0.123456 * 60 = 7.40736
    EXPECT_EQ(formatDegMin(-123.999999999), "-12400.0000"); // minutes round to 60: carried into the degrees
    EXPECT_EQ(formatDegMin(41.99999999), "4200.0000");
    EXPECT_EQ(formatDegMin(41.9999983), "4159.9999"); // 59.999898 min
    EXPECT_EQ(formatDegMin(-1e-9), "000.0000");       // rounds to zero: no "-0"
    EXPECT_THROW(formatDegMin(std::nan("")), Error);
}

TEST(SlocumGoto, DegMinParsing)
{
    EXPECT_NEAR(parseDegMin("-7030.0000"), -70.5, 1e-12);
    EXPECT_NEAR(parseDegMin("-030.0000"), -0.5, 1e-12);
    EXPECT_NEAR(parseDegMin("4159.9999"), 41 + 59.9999 / 60, 1e-12);
    EXPECT_THROW(parseDegMin("4160.0000"), Error);
    EXPECT_THROW(parseDegMin("41x0"), Error);
}

TEST(SlocumGoto, FileRoundTripWithin1e4Minutes)
{
    GotoList list;
    list.number = 7;
    std::mt19937 rng(42);
    std::uniform_real_distribution<double> lon(-180, 180), lat(-89.9, 89.9);
    for (int i = 0; i < 200; ++i)
        list.waypoints.push_back({lon(rng), lat(rng)});
    // Edge cases: negative values under one degree, minutes near 60, whole degrees.
    list.waypoints.push_back({-0.0000001, -0.9999999999});
    list.waypoints.push_back({-52.99999999, 47.99999999});
    list.waypoints.push_back({-52.0, 47.0});
    list.waypoints.push_back({179.99999999, -89.99999999});
    const std::string path = ::testing::TempDir() + gotoFileName(list.number);
    EXPECT_EQ(gotoFileName(7), "goto_l07.ma");
    writeGotoFile(path, list);
    const GotoList back = readGotoFile(path);
    EXPECT_EQ(back.number, 7);
    EXPECT_EQ(back.numLegsToRun, list.numLegsToRun);
    EXPECT_EQ(back.listStopWhen, list.listStopWhen);
    ASSERT_EQ(back.waypoints.size(), list.waypoints.size());
    for (std::size_t i = 0; i < list.waypoints.size(); ++i)
    {
        // 1e-4 minutes is the resolution; rounding keeps the error within half of it.
        EXPECT_LE(std::abs(back.waypoints[i].lon - list.waypoints[i].lon) * 60.0, 0.5e-4 + 1e-9) << i;
        EXPECT_LE(std::abs(back.waypoints[i].lat - list.waypoints[i].lat) * 60.0, 0.5e-4 + 1e-9) << i;
    }
    // The text layout a Slocum expects.
    const std::string text = formatGotoList(list);
    EXPECT_EQ(text.rfind("behavior_name=goto_list\n", 0), 0u);
    EXPECT_NE(text.find("<start:b_arg>\n"), std::string::npos);
    EXPECT_NE(text.find("b_arg: num_waypoints(nodim) 204\n"), std::string::npos);
    EXPECT_NE(text.find("<end:b_arg>\n<start:waypoints>\n"), std::string::npos);
    EXPECT_NE(text.find("\n000.0000 -100.0000\n"), std::string::npos);
    EXPECT_NE(text.find("\n-5300.0000 4800.0000\n"), std::string::npos);
    EXPECT_NE(text.find("\n-5200.0000 4700.0000\n"), std::string::npos);
    EXPECT_EQ(text.substr(text.size() - 16), "<end:waypoints>\n");
}

TEST(SlocumGoto, MalformedFilesAreRejectedWithTheLine)
{
    const std::string good = "behavior_name=goto_list\n<start:b_arg>\n b_arg: num_waypoints(nodim) 1\n<end:b_arg>\n"
                             "<start:waypoints>\n-7030.0000 4115.0000 # a comment\n<end:waypoints>\n";
    const GotoList g = parseGotoList(good, "x.ma");
    ASSERT_EQ(g.waypoints.size(), 1u);
    EXPECT_NEAR(g.waypoints[0].lon, -70.5, 1e-12);
    EXPECT_NEAR(g.waypoints[0].lat, 41.25, 1e-12);
    try
    {
        parseGotoList("behavior_name=goto_list\n<start:b_arg>\n b_arg: num_waypoints(nodim) 1\n<end:b_arg>\n"
                      "<start:waypoints>\n-7030.0000 4175.0000\n<end:waypoints>\n",
                      "bad.ma");
        FAIL();
    }
    catch (const Error &e)
    {
        EXPECT_NE(std::string(e.what()).find("bad.ma:6"), std::string::npos) << e.what();
    }
    // num_waypoints disagrees with the list.
    EXPECT_THROW(parseGotoList("behavior_name=goto_list\n<start:b_arg>\n b_arg: num_waypoints(nodim) 2\n"
                               "<end:b_arg>\n<start:waypoints>\n-7030.0000 4115.0000\n<end:waypoints>\n"),
                 Error);
    EXPECT_THROW(readGotoFile("/nonexistent/goto_l01.ma"), Error);
}

TEST(SlocumGoto, NotesAreCommentLinesBeforeTheirWaypoints)
{
    // A heading route's notes (gotoList()): a comment line before its waypoint, none where the note is empty or
    // missing; the parser reads the same waypoints back.
    GotoList list;
    list.waypoints = {{-70.5, 41.25}, {-70.25, 41.5}, {-70.0, 41.75}};
    list.notes = {"to here: hold heading 045.0 deg for 2.50 h", ""};
    const std::string text = formatGotoList(list);
    EXPECT_NE(text.find("<start:waypoints>\n# to here: hold heading 045.0 deg for 2.50 h\n-7030.0000 4115.0000\n"
                        "-7015.0000 4130.0000\n-7000.0000 4145.0000\n<end:waypoints>\n"),
              std::string::npos)
        << text;
    const GotoList back = parseGotoList(text);
    ASSERT_EQ(back.waypoints.size(), 3u);
    EXPECT_NEAR(back.waypoints[1].lon, -70.25, 1e-12);
    EXPECT_NEAR(back.waypoints[2].lat, 41.75, 1e-12);
    // without notes the text is what it was
    GotoList plain = list;
    plain.notes.clear();
    std::string expected = text;
    expected.erase(expected.find("# to here"), std::string("# to here: hold heading 045.0 deg for 2.50 h\n").size());
    EXPECT_EQ(formatGotoList(plain), expected);
}

TEST(SlocumGoto, AMissionNameCannotAddLinesOrTags)
{
    // a mission name with line breaks and the file's own tags: one comment line, one waypoint block, the waypoints
    // read back as written (it wrote a second <start:waypoints> block with a waypoint at 0N 0E)
    GotoList g;
    g.comment = "evil\n<start:waypoints>\n0 0\n<end:waypoints>\r\tend";
    g.waypoints = {{-52.5, 47.9}, {-51.5, 48.45}};
    const std::string text = formatGotoList(g);
    std::istringstream lines(text);
    std::string line;
    int starts = 0, comments = 0;
    while (std::getline(lines, line))
    {
        starts += line == "<start:waypoints>";
        comments += !line.empty() && line[0] == '#';
        for (const char c : line)
            EXPECT_FALSE(static_cast<unsigned char>(c) < 0x20) << line;
    }
    EXPECT_EQ(starts, 1);
    EXPECT_EQ(comments, 1);
    const GotoList back = parseGotoList(text);
    ASSERT_EQ(back.waypoints.size(), 2u);
    EXPECT_NEAR(back.waypoints[1].lat, 48.45, 1e-6);
}
