// make_global_forecast OUT.nc LON0 DLON NLON LAT0 DLAT NLAT [wrap] [land=LON0,LON1,LAT0,LAT1]
// Writes a Copernicus-Marine-like surface-current forecast with NetCDF-C (tests/current/GlobalForecast.h) for the
// command-line geography tests (check_geography.sh): global grids in either longitude convention, with or without
// the repeated seam column and the pole rows, regional extracts written across Greenwich, land blocks.
#include <cstdio>
#include <cstdlib>
#include <string>

#include "../current/GlobalForecast.h"

int main(int argc, char **argv)
{
    if (argc < 8)
    {
        std::fprintf(stderr, "usage: %s OUT.nc LON0 DLON NLON LAT0 DLAT NLAT [wrap] [land=LON0,LON1,LAT0,LAT1]\n",
                     argv[0]);
        return 2;
    }
    glider_test::GlobalForecastSpec s;
    s.lon0 = std::atof(argv[2]);
    s.dlon = std::atof(argv[3]);
    s.nlon = std::strtoul(argv[4], nullptr, 10);
    s.lat0 = std::atof(argv[5]);
    s.dlat = std::atof(argv[6]);
    s.nlat = std::strtoul(argv[7], nullptr, 10);
    for (int k = 8; k < argc; ++k)
    {
        const std::string a = argv[k];
        if (a == "wrap")
            s.wrapTo360 = true;
        else if (a.rfind("land=", 0) == 0 &&
                 std::sscanf(a.c_str() + 5, "%lf,%lf,%lf,%lf", &s.landLon0, &s.landLon1, &s.landLat0, &s.landLat1) == 4)
            continue;
        else
        {
            std::fprintf(stderr, "%s: unknown argument '%s'\n", argv[0], a.c_str());
            return 2;
        }
    }
    try
    {
        glider_test::writeGlobalForecast(argv[1], s);
    }
    catch (const std::exception &e)
    {
        std::fprintf(stderr, "%s: %s\n", argv[0], e.what());
        return 1;
    }
    return 0;
}
