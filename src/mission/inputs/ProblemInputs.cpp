// The one place a mission's inputs are read (ProblemInputs.h): resumed at the glider's last fix, then the forecast,
// its members and the truth, the planning frame, the glider's observations, the coastline and the bathymetry, each
// once, in the order in which each needs the ones before.
#include "InputsInternal.h"

#include <string>
#include <utility>

#include "ompl_glider/Config.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/current/CurrentField.h"
#include "ompl_glider/mission/Observations.h"
#include "ompl_glider/mission/SettingRanges.h"

namespace ompl_glider
{
using namespace inputs_detail;

ProblemInputs loadProblemInputs(MissionSpec spec)
{
    ProblemInputs in;
    in.spec = std::move(spec);
    MissionSpec &m = in.spec;
    in.frame.file = m.file;
    const std::string at = m.place("observations") + ": ";
#if OMPL_GLIDER_WITH_NETCDF
    try
    {
        in.observations = resumeAtLastFix(m); // replanning at sea: from the last fix, through the stations left
    }
    catch (const Error &e)
    {
        throw Error(at + e.what());
    }
#endif
    checkDatesInRange(m); // a time setting past the ISO years is refused naming it, before any field is read
    loadField(in);
    checkLastFixInForecast(in); // (before the stations' windows are judged against a departure past the forecast)
    loadMembers(in);
    loadTruth(in);
    in.frame.box = planningBox(in);
    estimateRunSpread(in); // with runs and a correction by the DAC: its priors from the runs' differences
    checkAnalyticFields(in);
    if (m.observations && m.observations->hasFiles())
    {
        if (!in.frame.isGeographic())
            throw Error(at + "a glider's observations are in lon/lat: the mission needs a geographic forecast or a "
                             "'projection'");
        try
        {
            if (!in.observations)
                in.observations = observationsOf(m);
        }
        catch (const Error &e)
        {
            throw Error(at + e.what());
        }
    }
    readCoastline(in);
    readDepthLimit(in);
    readDiveBathymetry(in);
    const FieldGrid *grid = (in.members.empty() ? in.field : in.members.front())->grid();
    if (grid)
        m.travel.maxStep = 0.5 * grid->minCellSize(); // no travel-time step passes over a grid node
    return in;
}
} // namespace ompl_glider
