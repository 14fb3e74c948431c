#include "ompl_glider/current/MeanderingJet.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ompl_glider
{
namespace
{
/// Quantities shared by the velocity and the Jacobian at one point.
struct JetTerms
{
    double g;   // sech^2(s)
    double gp;  // d sech^2(s) / ds = -2 sech^2(s) tanh(s)
    double D;   // sqrt(1 + k^2 B^2 sin^2(theta))
    double Dx;  // dD/dx
    double Dxx; // d2D/dx2
    double N;   // y - B cos(theta)
    double Nx;  // dN/dx
    double Nxx; // d2N/dx2
    double sx;  // ds/dx
};

/// B(t) = B0 + eps cos(omega t + theta). The planners ask for many points at one time (a front, a lattice layer, the
/// stages of a step), so each thread keeps its last time and amplitude: one cosine per time, not per point.
double amplitude(const MeanderingJetParams &p, double t)
{
    if (p.epsilon == 0.0)
        return p.B0;
    struct Last
    {
        double t, B0, epsilon, omega, theta, B;
    };
    thread_local Last last{std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0, 0.0, 0.0, 0.0};
    if (t != last.t || p.B0 != last.B0 || p.epsilon != last.epsilon || p.omega != last.omega || p.theta != last.theta)
        last = {t, p.B0, p.epsilon, p.omega, p.theta, p.B0 + p.epsilon * std::cos(p.omega * t + p.theta)};
    return last.B;
}

/// tanh(s) and sech^2(s) = 1 - tanh^2(s) from one exponential, a = exp(-2|s|): tanh = sign(s) (1 - a) / (1 + a),
/// sech^2 = 4 a / (1 + a)^2 (no cancellation; glibc's tanh takes an expm1, about twice an exp).
void tanhSech2(double s, double &th, double &sech2)
{
    const double a = std::exp(-2.0 * std::abs(s));
    const double d = 1.0 / (1.0 + a);
    th = std::copysign((1.0 - a) * d, s);
    sech2 = 4.0 * a * d * d;
}

JetTerms jetTerms(const MeanderingJetParams &p, double x, double y, double t)
{
    const double B = amplitude(p, t);
    const double th = p.k * (x - p.c * t);
    const double sn = std::sin(th), cs = std::cos(th);
    JetTerms j{};
    j.N = y - B * cs;
    j.Nx = B * p.k * sn;
    j.Nxx = B * p.k * p.k * cs;
    j.D = std::sqrt(1.0 + p.k * p.k * B * B * sn * sn);
    const double P = p.k * p.k * p.k * B * B * sn * cs; // = D * Dx
    const double Px = p.k * p.k * p.k * p.k * B * B * (cs * cs - sn * sn);
    j.Dx = P / j.D;
    j.Dxx = Px / j.D - P * j.Dx / (j.D * j.D);
    const double s = j.N / j.D;
    double th_s = 0.0;
    tanhSech2(s, th_s, j.g);
    j.gp = -2.0 * j.g * th_s;
    j.sx = j.Nx / j.D - j.N * j.Dx / (j.D * j.D);
    return j;
}

/// Speed as a function of the invariant coordinates (s, theta, B).
double speedInvariant(const MeanderingJetParams &p, double s, double th, double B)
{
    const double sn = std::sin(th), cs = std::cos(th);
    const double D = std::sqrt(1.0 + p.k * p.k * B * B * sn * sn);
    const double Dx = p.k * p.k * p.k * B * B * sn * cs / D;
    const double sx = B * p.k * sn / D - s * Dx / D;
    const double th_s = std::tanh(s);
    const double g = 1.0 - th_s * th_s;
    return g * std::sqrt(1.0 / (D * D) + sx * sx);
}

/// Global maximum of the speed over all (x, y, t) with a 0.5% margin (see MeanderingJet::maxSpeed).
double globalSpeedBound(const MeanderingJetParams &p)
{
    // The speed depends on (x, y, t) only through s = N/D, theta = k(x - ct) and B(t), so its global maximum is
    // a maximum over a compact box: s in [-6, 6] (sech^2 is < 2.5e-5 beyond), theta in [0, 2pi), B in
    // [B0 - |eps|, B0 + |eps|]. Grid search, then a local refinement by shrinking a pattern around the best point.
    const double bLo = p.B0 - std::abs(p.epsilon), bHi = p.B0 + std::abs(p.epsilon);
    double best = 0.0, bs = 0.0, bt = 0.0, bb = p.B0;
    const int ns = 241, nt = 256, nb = 9;
    for (int ib = 0; ib < nb; ++ib)
    {
        const double B = bLo + (bHi - bLo) * ib / (nb - 1);
        for (int it = 0; it < nt; ++it)
        {
            const double th = 2.0 * M_PI * it / nt;
            for (int is = 0; is < ns; ++is)
            {
                const double s = -6.0 + 12.0 * is / (ns - 1);
                const double sp = speedInvariant(p, s, th, B);
                if (sp > best)
                {
                    best = sp;
                    bs = s;
                    bt = th;
                    bb = B;
                }
            }
        }
    }
    double ds = 0.05, dt = 0.05, db = (bHi - bLo) / 8.0;
    for (int iter = 0; iter < 200; ++iter)
    {
        bool improved = false;
        for (int a = -1; a <= 1; ++a)
            for (int b = -1; b <= 1; ++b)
                for (int c = -1; c <= 1; ++c)
                {
                    const double B = std::clamp(bb + c * db, bLo, bHi);
                    const double sp = speedInvariant(p, bs + a * ds, bt + b * dt, B);
                    if (sp > best)
                    {
                        best = sp;
                        bs += a * ds;
                        bt += b * dt;
                        bb = B;
                        improved = true;
                    }
                }
        if (!improved)
        {
            ds *= 0.5;
            dt *= 0.5;
            db *= 0.5;
        }
    }
    return best * 1.005;
}
} // namespace

MeanderingJet::MeanderingJet(MeanderingJetParams params) : p_(params) {}

double MeanderingJet::maxSpeed(const Region & /*region*/) const
{
    std::call_once(boundOnce_, [this] { speedBound_ = globalSpeedBound(p_); });
    return speedBound_;
}

std::optional<double> MeanderingJet::streamFunction(double x, double y, double /*z*/, double t) const
{
    const double B = p_.B0 + p_.epsilon * std::cos(p_.omega * t + p_.theta);
    const double th = p_.k * (x - p_.c * t);
    const double D = std::sqrt(1.0 + p_.k * p_.k * B * B * std::sin(th) * std::sin(th));
    return 1.0 - std::tanh((y - B * std::cos(th)) / D);
}

Velocity MeanderingJet::evaluate(double x, double y, double /*z*/, double t) const
{
    const JetTerms j = jetTerms(p_, x, y, t);
    // phi = 1 - tanh(s): u = -phi_y = g s_y = g / D ; v = phi_x = -g s_x
    return {j.g / j.D, -j.g * j.sx};
}

Jacobian MeanderingJet::evaluateJacobian(double x, double y, double /*z*/, double t) const
{
    const JetTerms j = jetTerms(p_, x, y, t);
    const double D2 = j.D * j.D;
    const double sy = 1.0 / j.D;
    const double sxy = -j.Dx / D2;
    const double sxx = j.Nxx / j.D - 2.0 * j.Nx * j.Dx / D2 - j.N * j.Dxx / D2 + 2.0 * j.N * j.Dx * j.Dx / (D2 * j.D);
    Jacobian J;
    J.ux = j.gp * j.sx / j.D - j.g * j.Dx / D2;
    J.uy = j.gp * sy / j.D;
    J.vx = -j.gp * j.sx * j.sx - j.g * sxx;
    J.vy = -j.gp * sy * j.sx - j.g * sxy;
    return J;
}
} // namespace ompl_glider
