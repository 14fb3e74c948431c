// Bearing optimisation with NLopt's Subplex ([IsernObstacles] Sec. II.2); see BearingOptimizer.h.
#include "ompl_glider/routes/BearingOptimizer.h"

#include <cmath>
#include <stdexcept>

#include <nlopt.hpp>

namespace ompl_glider
{
BearingOptimizerResult optimiseBearings(const StintSimulator &sim, std::vector<double> initial,
                                        const BearingOptimizerParams &params)
{
    BearingOptimizerResult out;
    const std::size_t n = sim.settings().stintCount();
    if (initial.empty())
        initial = sim.direct().bearings;
    while (initial.size() < n)
        initial.push_back(initial.empty() ? 0.0 : initial.back());
    initial.resize(n);
    out.initial = sim.simulate(initial, false);
    out.evaluations = 1;
    double bestCost = out.initial.cost;
    std::vector<double> best = initial;

    nlopt::opt opt(nlopt::LN_SBPLX, static_cast<unsigned>(n));
    std::vector<double> lo(n), hi(n), step(n, params.initialStep);
    for (std::size_t k = 0; k < n; ++k)
    {
        lo[k] = initial[k] - 180.0;
        hi[k] = initial[k] + 180.0;
    }
    opt.set_lower_bounds(lo);
    opt.set_upper_bounds(hi);
    opt.set_initial_step(step);
    opt.set_xtol_abs(params.bearingTolerance);
    opt.set_maxeval(static_cast<int>(std::max(1u, params.maxEvaluations - 1)));
    struct Data
    {
        const StintSimulator *sim;
        BearingOptimizerResult *out;
        double *bestCost;
        std::vector<double> *best;
        const BearingOptimizerParams *params;
        nlopt::opt *opt;
    } data{&sim, &out, &bestCost, &best, &params, &opt};
    opt.set_min_objective(
        [](const std::vector<double> &x, std::vector<double> &, void *d) -> double {
            Data &D = *static_cast<Data *>(d);
            ++D.out->evaluations;
            const double c = D.sim->simulate(x, false).cost;
            if (c < *D.bestCost)
            {
                *D.bestCost = c;
                *D.best = x;
            }
            if (D.params->stop && D.params->stop())
                D.opt->force_stop();
            return std::isfinite(c) ? c : 1e300;
        },
        &data);
    std::vector<double> x = initial;
    double f = 0.0;
    try
    {
        opt.optimize(x, f);
    }
    catch (const nlopt::forced_stop &)
    {
    }
    catch (const nlopt::roundoff_limited &)
    {
    }
    catch (const std::runtime_error &) // NLopt's generic failure: the best point evaluated is kept
    {
    }
    out.plan = sim.simulate(best);
    for (double &b : out.plan.bearings) // reported in [0, 360) (flown as optimised)
        b = std::fmod(std::fmod(b, 360.0) + 360.0, 360.0);
    return out;
}
} // namespace ompl_glider
