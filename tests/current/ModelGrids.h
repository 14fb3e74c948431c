#pragma once
// Model grids as ocean models write them, written with NetCDF-C for the tests: a global curvilinear
// grid whose i-index wraps (WrapGrid) and a ROMS-like Arakawa C grid (RomsGrid). Both come from an analytic
// eastward/northward current, so that the loaded field and the planned routes can be checked against it.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "TestNetCdfUtil.h"
#include "ompl_glider/Geometry.h"
#include "ompl_glider/current/LocalProjection.h"

namespace glider_test
{
using ompl_glider::LocalProjection;
using ompl_glider::LonLat;
using ompl_glider::Point2;
constexpr double kDeg = M_PI / 180.0;

// ---- a global curvilinear grid whose i-index wraps ----

/// Eastward/northward current of the wrapping grid (smooth, periodic in longitude).
void wrapCurrent(double lon, double lat, double &u, double &v)
{
    u = 0.2 + 0.05 * std::sin(lon * kDeg) * std::cos(lat * kDeg);
    v = 0.04 * std::cos(2.0 * lon * kDeg);
}

/// 120 columns of 3 degrees starting at 40W (the index seam between column 119 at 43W and column 0 at 40W, in the
/// Atlantic), rows 40S..40N every 2 degrees, sheared (longitude grows by 0.2 degree per row) so that the grid is
/// truly curvilinear; longitudes stored in -180..180 (a second seam, of the values, near column 73). With
/// `repeat`, a 121st column repeats column 0 (as some global files write their seam).
struct WrapGrid
{
    static constexpr std::size_t kCols = 120, kRows = 41;
    bool repeat{false};
    /// land (fill values): the nodes of rows landRows[0]..landRows[1] and columns landCols[0]..landCols[1] (in
    /// index order across the seam: 118..1 is 118, 119, 0, 1); none when landRows[0] > landRows[1]
    std::size_t landRows[2]{1, 0}, landCols[2]{0, 0};
    bool land(std::size_t j, std::size_t i) const
    {
        if (landRows[0] > landRows[1] || j < landRows[0] || j > landRows[1])
            return false;
        i %= kCols;
        const std::size_t a = landCols[0], b = landCols[1];
        return a <= b ? (i >= a && i <= b) : (i >= a || i <= b);
    }
    double lon(std::size_t j, std::size_t i) const
    {
        return ompl_glider::normalizeLongitude(-40.0 + 3.0 * double(i % kCols) + 0.2 * double(j));
    }
    double lat(std::size_t j, std::size_t) const { return -40.0 + 2.0 * double(j); }
    std::size_t columns() const { return kCols + (repeat ? 1 : 0); }
    void write(const std::string &path) const
    {
        NcWriter w(path);
        const int dt = w.dim("time", 2), dj = w.dim("nj", kRows), di = w.dim("ni", columns());
        const int vt = w.var("time", NC_DOUBLE, {dt});
        const int la = w.var("TLAT", NC_DOUBLE, {dj, di}), lo = w.var("TLONG", NC_DOUBLE, {dj, di});
        w.text(vt, "units", "days since 2026-03-01");
        w.text(la, "units", "degrees_north");
        w.text(lo, "units", "degrees_east");
        const int u = w.var("uo", NC_FLOAT, {dt, dj, di}), v = w.var("vo", NC_FLOAT, {dt, dj, di});
        for (int var : {u, v})
        {
            w.fill(var, NC_FLOAT, 1e20);
            w.text(var, "units", "m/s");
            w.text(var, "coordinates", "TLONG TLAT");
        }
        w.text(u, "standard_name", "eastward_sea_water_velocity");
        w.text(v, "standard_name", "northward_sea_water_velocity");
        w.enddef();
        w.put(vt, {0.0, 30.0});
        std::vector<double> pla, plo, pu, pv;
        for (std::size_t j = 0; j < kRows; ++j)
            for (std::size_t i = 0; i < columns(); ++i)
            {
                pla.push_back(lat(j, i));
                plo.push_back(lon(j, i));
            }
        for (int rec = 0; rec < 2; ++rec)
            for (std::size_t j = 0; j < kRows; ++j)
                for (std::size_t i = 0; i < columns(); ++i)
                {
                    double a, b;
                    wrapCurrent(lon(j, i), lat(j, i), a, b);
                    pu.push_back(land(j, i) ? 1e20 : a);
                    pv.push_back(land(j, i) ? 1e20 : b);
                }
        w.put(la, pla);
        w.put(lo, plo);
        w.put(u, pu);
        w.put(v, pv);
    }
};

// ---- a ROMS-like C grid ----

/// A rotated rectangular grid of cell centres (rho points) 5 km apart, at angle theta (radians, from east to the
/// grid's xi direction) about (-70, 40): positions in a local plane, then lon/lat through a LocalProjection.
struct RomsGrid
{
    static constexpr std::size_t kEta = 14, kXi = 18;
    double theta{30.0 * kDeg};
    double d{5000.0};
    /// false: no `angle` variable (the loader derives it from lon_rho/lat_rho)
    bool writeAngle{true};
    LocalProjection proj{-70.0, 40.0};
    /// Local plane position of the point at fractional indices (eta, xi) of the rho grid.
    Point2 at(double eta, double xi) const
    {
        const double a = xi - 0.5 * kXi, b = eta - 0.5 * kEta;
        return {d * (a * std::cos(theta) - b * std::sin(theta)), d * (a * std::sin(theta) + b * std::cos(theta))};
    }
    LonLat geo(double eta, double xi) const
    {
        const Point2 p = at(eta, xi);
        return proj.inverse(p.x, p.y);
    }
    /// The true current, eastward/northward, linear in the plane position (so the mean of two faces is the value
    /// at the centre between them).
    static void current(Point2 p, double &ue, double &vn)
    {
        ue = 0.25 + 4e-6 * p.x - 2e-6 * p.y;
        vn = -0.1 + 3e-6 * p.y + 1e-6 * p.x;
    }
    /// Land: a block of rho points.
    static bool land(std::size_t eta, std::size_t xi) { return eta >= 9 && eta <= 11 && xi >= 11 && xi <= 14; }
    /// With sLevels > 0: terrain-following s-levels (ROMS Vtransform 2, CF ocean_s_coordinate_g2), sea surface
    /// zeta, and the current scaled by depthFactor(z) at each level's depth z (m, negative down).
    std::size_t sLevels{0};
    double hc{20.0}, zeta{0.5};
    /// s of level k (bottom first, as ROMS) and its stretching C(s) = -s^2.
    double sOf(std::size_t k) const { return -1.0 + (double(k) + 0.5) / double(sLevels); }
    static double stretch(double s) { return -s * s; }
    /// Bathymetry: 200 m, 30 m on a shallow bank (rows 2..4, columns 12..15).
    static double bottom(std::size_t eta, std::size_t xi)
    {
        return eta >= 2 && eta <= 4 && xi >= 12 && xi <= 15 ? 30.0 : 200.0;
    }
    /// Depth z (m, negative down) of level k where the bottom is h ([CF] ocean_s_coordinate_g2).
    double levelZ(std::size_t k, double h) const
    {
        const double S = (hc * sOf(k) + h * stretch(sOf(k))) / (hc + h);
        return zeta + (zeta + h) * S;
    }
    static double depthFactor(double z) { return 1.0 + z / 250.0; }
    /// Writes the file; grid components u along xi, v along eta (u = e cos + n sin, v = -e sin + n cos).
    void write(const std::string &path, bool masks = true) const
    {
        NcWriter w(path, NC_CLOBBER); // classic format, as ROMS writes
        const int dt = w.dim("ocean_time", 2), er = w.dim("eta_rho", kEta), xr = w.dim("xi_rho", kXi);
        const int eu = w.dim("eta_u", kEta), xu = w.dim("xi_u", kXi - 1);
        const int ev = w.dim("eta_v", kEta - 1), xv = w.dim("xi_v", kXi);
        const int vt = w.var("ocean_time", NC_DOUBLE, {dt});
        w.text(vt, "units", "seconds since 2026-04-01 00:00:00");
        auto coord = [&](const char *name, int a, int b, const char *units) {
            const int v = w.var(name, NC_DOUBLE, {a, b});
            w.text(v, "units", units);
            return v;
        };
        const int lonr = coord("lon_rho", er, xr, "degree_east"), latr = coord("lat_rho", er, xr, "degree_north");
        const int lonu = coord("lon_u", eu, xu, "degree_east"), latu = coord("lat_u", eu, xu, "degree_north");
        const int lonv = coord("lon_v", ev, xv, "degree_east"), latv = coord("lat_v", ev, xv, "degree_north");
        const int ang = writeAngle ? w.var("angle", NC_DOUBLE, {er, xr}) : -1;
        if (writeAngle)
        {
            w.text(ang, "units", "radians");
            w.text(ang, "long_name", "angle between XI-axis and EAST");
        }
        int mr = -1, mu = -1, mv = -1;
        if (masks)
        {
            mr = w.var("mask_rho", NC_DOUBLE, {er, xr});
            mu = w.var("mask_u", NC_DOUBLE, {eu, xu});
            mv = w.var("mask_v", NC_DOUBLE, {ev, xv});
            for (int m : {mr, mu, mv})
                w.text(m, "flag_meanings", "land water"), w.num(m, "flag_values", NC_DOUBLE, {0.0, 1.0});
        }
        int ds = -1, vs = -1, vc = -1, vhc = -1, vh = -1, vzeta = -1;
        if (sLevels > 0)
        {
            ds = w.dim("s_rho", sLevels);
            vs = w.var("s_rho", NC_DOUBLE, {ds});
            w.text(vs, "standard_name", "ocean_s_coordinate_g2");
            w.text(vs, "positive", "up");
            w.text(vs, "formula_terms", "s: s_rho C: Cs_r eta: zeta depth: h depth_c: hc");
            vc = w.var("Cs_r", NC_DOUBLE, {ds});
            vhc = w.var("hc", NC_DOUBLE, {});
            vh = w.var("h", NC_DOUBLE, {er, xr});
            w.text(vh, "units", "meter");
            vzeta = w.var("zeta", NC_DOUBLE, {dt, er, xr});
            w.text(vzeta, "units", "meter");
        }
        const std::vector<int> udims = sLevels > 0 ? std::vector<int>{dt, ds, eu, xu} : std::vector<int>{dt, eu, xu};
        const std::vector<int> vdims = sLevels > 0 ? std::vector<int>{dt, ds, ev, xv} : std::vector<int>{dt, ev, xv};
        const int u = w.var("u", NC_FLOAT, udims), v = w.var("v", NC_FLOAT, vdims);
        w.text(u, "units", "meter second-1");
        w.text(v, "units", "meter second-1");
        w.text(u, "coordinates", "lon_u lat_u ocean_time");
        w.text(v, "coordinates", "lon_v lat_v ocean_time");
        w.fill(u, NC_FLOAT, 1e37);
        w.fill(v, NC_FLOAT, 1e37);
        w.enddef();
        w.put(vt, {0.0, 5.0 * 86400.0});
        std::vector<double> a, b;
        auto grid = [&](std::size_t ne, std::size_t nxi, double de, double dx, int var1, int var2) {
            a.clear();
            b.clear();
            for (std::size_t j = 0; j < ne; ++j)
                for (std::size_t i = 0; i < nxi; ++i)
                {
                    const LonLat g = geo(double(j) + de, double(i) + dx);
                    a.push_back(g.lon);
                    b.push_back(g.lat);
                }
            w.put(var1, a);
            w.put(var2, b);
        };
        grid(kEta, kXi, 0, 0, lonr, latr);
        grid(kEta, kXi - 1, 0, 0.5, lonu, latu);
        grid(kEta - 1, kXi, 0.5, 0, lonv, latv);
        if (writeAngle)
            w.put(ang, std::vector<double>(kEta * kXi, theta));
        auto landU = [](std::size_t j, std::size_t i) { return land(j, i) || land(j, i + 1); };
        auto landV = [](std::size_t j, std::size_t i) { return land(j, i) || land(j + 1, i); };
        if (masks)
        {
            std::vector<double> m;
            for (std::size_t j = 0; j < kEta; ++j)
                for (std::size_t i = 0; i < kXi; ++i)
                    m.push_back(land(j, i) ? 0.0 : 1.0);
            w.put(mr, m);
            m.clear();
            for (std::size_t j = 0; j < kEta; ++j)
                for (std::size_t i = 0; i + 1 < kXi; ++i)
                    m.push_back(landU(j, i) ? 0.0 : 1.0);
            w.put(mu, m);
            m.clear();
            for (std::size_t j = 0; j + 1 < kEta; ++j)
                for (std::size_t i = 0; i < kXi; ++i)
                    m.push_back(landV(j, i) ? 0.0 : 1.0);
            w.put(mv, m);
        }
        if (sLevels > 0)
        {
            std::vector<double> sv, cv, hv;
            for (std::size_t k = 0; k < sLevels; ++k)
                sv.push_back(sOf(k)), cv.push_back(stretch(sOf(k)));
            for (std::size_t j = 0; j < kEta; ++j)
                for (std::size_t i = 0; i < kXi; ++i)
                    hv.push_back(bottom(j, i));
            w.put(vs, sv);
            w.put(vc, cv);
            w.put(vhc, {hc});
            w.put(vh, hv);
            w.put(vzeta, std::vector<double>(2 * kEta * kXi, zeta));
        }
        // a face's level lies at the depth of its bottom (the mean of the two rho points' bottoms)
        auto factor = [&](std::size_t k, double h) { return sLevels > 0 ? depthFactor(levelZ(k, h)) : 1.0; };
        std::vector<double> pu, pv;
        for (int rec = 0; rec < 2; ++rec)
        {
            for (std::size_t k = 0; k < std::max<std::size_t>(1, sLevels); ++k)
                for (std::size_t j = 0; j < kEta; ++j)
                    for (std::size_t i = 0; i + 1 < kXi; ++i)
                    {
                        double ue, vn;
                        current(at(double(j), double(i) + 0.5), ue, vn);
                        const double f = factor(k, 0.5 * (bottom(j, i) + bottom(j, i + 1)));
                        pu.push_back(landU(j, i) ? 1e37 : f * (ue * std::cos(theta) + vn * std::sin(theta)));
                    }
            for (std::size_t k = 0; k < std::max<std::size_t>(1, sLevels); ++k)
                for (std::size_t j = 0; j + 1 < kEta; ++j)
                    for (std::size_t i = 0; i < kXi; ++i)
                    {
                        double ue, vn;
                        current(at(double(j) + 0.5, double(i)), ue, vn);
                        const double f = factor(k, 0.5 * (bottom(j, i) + bottom(j + 1, i)));
                        pv.push_back(landV(j, i) ? 1e37 : f * (-ue * std::sin(theta) + vn * std::cos(theta)));
                    }
        }
        w.put(u, pu);
        w.put(v, pv);
    }
};
} // namespace glider_test
