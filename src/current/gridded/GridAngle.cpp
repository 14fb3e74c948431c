// The angle of a curvilinear grid's i direction derived from its nodes' coordinates (as ROMS' grid tools compute
// `angle`), for grid-relative velocities in a file without an angle variable; the checks that refuse a grid whose
// directions are ambiguous.
#include <algorithm>
#include <cmath>

#include "GriddedInternal.h"

namespace ompl_glider
{
namespace gridded_detail
{
namespace
{
constexpr double kRadToDeg = 180.0 / M_PI;
constexpr double kWgs84E2 = 6.69437999014e-3; // first eccentricity squared of WGS84

/// Angle in (-pi, pi].
double wrapAngle(double a)
{
    while (a > M_PI)
        a -= 2.0 * M_PI;
    while (a <= -M_PI)
        a += 2.0 * M_PI;
    return a;
}

/// Degrees in [-180, 180).
double wrapDegrees(double d)
{
    return d - 360.0 * std::floor((d + 180.0) / 360.0);
}

/// The coordinate difference (b - a) along one grid line at index k of n points (values at k - 1, k, k + 1 or the
/// second-order one-sided formula at the ends); longitude differences wrapped.
template <class At> double difference(const At &at, std::size_t k, std::size_t n, bool lon)
{
    auto d = [lon](double b, double a) { return lon ? wrapDegrees(b - a) : b - a; };
    if (n == 2)
        return d(at(1), at(0));
    if (k == 0)
        return 2.0 * d(at(1), at(0)) - 0.5 * d(at(2), at(0));
    if (k + 1 == n)
        return 2.0 * d(at(n - 1), at(n - 2)) - 0.5 * d(at(n - 1), at(n - 3));
    return 0.5 * d(at(k + 1), at(k - 1));
}
} // namespace

DerivedGridAngle deriveGridAngle(const std::vector<double> &x, const std::vector<double> &y, std::size_t nx,
                                 std::size_t ny, bool geographic)
{
    DerivedGridAngle r;
    if (nx < 2 || ny < 2)
    {
        r.fault = "the grid has a single node along " + std::string(nx < 2 ? "i" : "j") +
                  ", so its directions cannot be derived";
        return r;
    }
    const std::size_t nh = nx * ny;
    r.radians.resize(nh);
    std::vector<double> jAngle(nh);
    for (std::size_t j = 0; j < ny; ++j)
        for (std::size_t i = 0; i < nx; ++i)
        {
            const std::size_t n = j * nx + i;
            auto alongI = [&](const std::vector<double> &v) {
                return [&v, j, nx](std::size_t k) { return v[j * nx + k]; };
            };
            auto alongJ = [&](const std::vector<double> &v) {
                return [&v, i, nx](std::size_t k) { return v[k * nx + i]; };
            };
            double xi = difference(alongI(x), i, nx, geographic), yi = difference(alongI(y), i, nx, false);
            double xj = difference(alongJ(x), j, ny, geographic), yj = difference(alongJ(y), j, ny, false);
            if (geographic)
            {
                // east and north lengths of a degree on WGS84: N cos(lat) and M, M / N = (1 - e2) / (1 - e2 sin^2)
                const double phi = y[n] * M_PI / 180.0, s = std::sin(phi);
                const double ratio = (1.0 - kWgs84E2) / (1.0 - kWgs84E2 * s * s);
                xi *= std::cos(phi);
                xj *= std::cos(phi);
                yi *= ratio;
                yj *= ratio;
            }
            r.radians[n] = std::atan2(yi, xi);
            jAngle[n] = std::atan2(yj, xj);
            r.maxAbsDegrees = std::max(r.maxAbsDegrees, std::abs(r.radians[n]) * kRadToDeg);
            r.minDegrees = std::min(r.minDegrees, r.radians[n] * kRadToDeg);
            r.maxDegrees = std::max(r.maxDegrees, r.radians[n] * kRadToDeg);
        }
    r.rotated = r.maxAbsDegrees > kGridRotatedDegrees;
    if (!r.rotated)
        return r;
    // Grid-relative (u, v) are along i and j: j must run about 90 degrees counter-clockwise of i (a right-handed,
    // near-orthogonal grid, as ROMS and NEMO write them), and i must not turn sharply between neighbours.
    for (std::size_t j = 0; j < ny && r.fault.empty(); ++j)
        for (std::size_t i = 0; i < nx && r.fault.empty(); ++i)
        {
            const std::size_t n = j * nx + i;
            const double between = wrapAngle(jAngle[n] - r.radians[n]) * kRadToDeg;
            if (std::abs(between - 90.0) > kGridSkewDegrees)
            {
                r.fault = "its j direction lies " + text::number(between, 4) +
                          " degrees counter-clockwise of its i direction (expected about 90: a right-handed, "
                          "near-orthogonal grid)";
                r.faultJ = j, r.faultI = i;
            }
            for (const std::size_t m : {i + 1 < nx ? n + 1 : n, j + 1 < ny ? n + nx : n})
            {
                const double turn = std::abs(wrapAngle(r.radians[m] - r.radians[n])) * kRadToDeg;
                if (m != n && turn > kGridTurnDegrees && r.fault.empty())
                {
                    r.fault = "its i direction turns by " + text::number(turn, 4) +
                              " degrees between neighbouring nodes (at most " + text::number(kGridTurnDegrees) +
                              " expected)";
                    r.faultJ = j, r.faultI = i;
                }
            }
        }
    return r;
}

std::string gridAngleNote(const DerivedGridAngle &a, const std::string &coordinates)
{
    return "derived from " + coordinates + ": the grid's i direction " + text::number(a.minDegrees, 4) + ".." +
           text::number(a.maxDegrees, 4) + " degrees counter-clockwise from east";
}
} // namespace gridded_detail
} // namespace ompl_glider
