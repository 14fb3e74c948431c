// Planning on a NetCDF forecast with the library API, as glider_plan --currents does, and writing the pilot's files
// (summary.json, waypoints.csv, path.csv, path.geojson, the Slocum goto list, the map):
//   demo_forecast FORECAST.nc OUTDIR
#include <iostream>
#include <string>

#include "ompl_glider/Exception.h"
#include "ompl_glider/mission/ForecastMission.h"
#include "ompl_glider/mission/Planning.h"
#include "ompl_glider/output/OutputWriter.h"

int main(int argc, char **argv)
{
    if (argc != 3)
    {
        std::cerr << "usage: demo_forecast FORECAST.nc OUTDIR\n";
        return 2;
    }
    try
    {
        ompl_glider::ForecastInput in; // the forecast and the trip, as the flags of glider_plan --currents
        in.current.file = argv[1];
        in.start = {-52.7, 47.9}; // lon, lat
        in.goal = {-51.5, 48.45};
        in.departure = "2026-03-15T06:00:00Z";
        in.speed = 0.3; // m/s
        ompl_glider::MissionSpec spec = ompl_glider::forecastMission(in);
        spec.planner.gridSize = 4000; // metres
        spec.outputs.directory = argv[2];

        const ompl_glider::MissionProblem problem(spec);                            // the one problem description
        const ompl_glider::MissionResult result = ompl_glider::runMission(problem); // the one pipeline
        if (!result.plan.solved)
        {
            std::cout << "no path: " << result.plan.reason << "\n";
            return 1;
        }
        std::cout << result.plan.planner << ": " << result.plan.travelTime / 3600.0 << " h, " << result.waypoints.size()
                  << " waypoints\n";
        for (const std::string &file : ompl_glider::writeOutputs(result, problem)) // the one output layer
            std::cout << "wrote " << file << "\n";
        return 0;
    }
    catch (const ompl_glider::Error &e)
    {
        std::cerr << "demo_forecast: " << e.what() << "\n";
        return 2;
    }
}
