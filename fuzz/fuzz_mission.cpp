// Fuzz target: mission files. Bytes -> parseMission() (YAML, every field checked) and, when the text parses, the
// MissionProblem (field, projection, box, start/goal, forbidden regions) without planning. ompl_glider::Error is the
// expected answer to a bad mission; any other exception, a crash, a sanitizer report or a hang is a finding.
//
// A mission may name files (current.file, forbidden.geojson, dive_profile.bathymetry.file): the process works in an
// empty temporary directory, so relative names only ever meet missing files, and a mission that names a file
// outside that directory (an absolute path, "..") is parsed but not built into a problem.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <unistd.h>

#include "FuzzUtil.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/MissionSpec.h"

namespace
{
std::string gDir; // the empty working directory

/// True when @p path names nothing or a place inside the empty directory.
bool insideScratch(const std::string &path)
{
    if (path.empty())
        return true;
    if (path.compare(0, gDir.size() + 1, gDir + "/") != 0 && path != gDir)
        return false;
    return path.find("/..") == std::string::npos;
}
} // namespace

extern "C" int LLVMFuzzerInitialize(int *, char ***)
{
    setenv("OMPL_GLIDER_MEMORY_LIMIT", "256M", 1);
    gDir = ompl_glider_fuzz::scratchDirectory("fuzz_mission");
    if (chdir(gDir.c_str()) != 0)
        std::abort();
    ompl_glider_fuzz::quietOmpl();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const std::string text(reinterpret_cast<const char *>(data), size);
    ompl_glider::MissionSpec spec;
    try
    {
        spec = ompl_glider::parseMission(text, "fuzz.yaml", gDir);
    }
    catch (const ompl_glider::Error &)
    {
        return 0;
    }
    const bool netcdf = spec.current.isForecast();
    if ((netcdf && !insideScratch(spec.current.file)) || !insideScratch(spec.forbidden.geojson) ||
        (spec.dive.bathymetry == ompl_glider::DiveSpec::Bathymetry::File && !insideScratch(spec.dive.bathymetryFile)))
        return 0;
    try
    {
        const ompl_glider::MissionProblem problem(spec);
        if (problem.isGeographic())
            (void)problem.toGeographic(problem.getStart());
    }
    catch (const ompl_glider::Error &)
    {
    }
    return 0;
}
