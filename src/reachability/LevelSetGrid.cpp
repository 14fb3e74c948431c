/// @file LevelSetGrid.cpp
/// @brief LevelSetSolver's construction: its parameters checked, the grid over the region and the forbidden set
/// prepared once (land and static regions as signed distances, time-windowed zones, ice zones and other
/// environments kept for the steps); and the planner's default cell. The steps of solve() are in LevelSet.cpp.

#include "ompl_glider/reachability/LevelSet.h"
#include "../io/NumberText.h"

#include <algorithm>
#include <cmath>

#include "LevelSetInternal.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/ResourceLimits.h"
#include "ompl_glider/environment/ForbiddenRegions.h"
#include "ompl_glider/environment/IceZone.h"
#include "ompl_glider/environment/StaticRegion.h"
#include "ompl_glider/environment/TimeWindowedZone.h"

namespace ompl_glider
{
LevelSetSolver::LevelSetSolver(std::shared_ptr<const GliderContext> ctx, LevelSetParams params)
    : ctx_(std::move(ctx)), params_(params), impl_(std::make_unique<Impl>())
{
    using levelset_detail::Grid;
    using levelset_detail::maskDistance;
    using levelset_detail::polygonDistance;
    using levelset_detail::SparseDistance;
    if (!ctx_ || !ctx_->field || !ctx_->travel)
        throw Error("LevelSetSolver: the problem context is null or has no field");
    if (!(params_.cellSize > 0.0) || !std::isfinite(params_.cellSize))
        throw Error("LevelSet: resolution (cell size) must be > 0, got " + text::number(params_.cellSize));
    if (!(params_.cfl >= 0.0 && params_.cfl <= 8.0))
        throw Error("LevelSet: cfl must be in (0, 8] (0: automatic), got " + text::number(params_.cfl));
    if (!(params_.clearance >= 0.0) || !std::isfinite(params_.clearance))
        throw Error("LevelSet: clearance must be >= 0, got " + text::number(params_.clearance));
    if (!(params_.band >= 4.0 && params_.band <= 50.0))
        throw Error("LevelSet: band must be in [4, 50] cells, got " + std::to_string(params_.band));
    const Region &r = ctx_->region;
    if (!std::isfinite(r.xMin) || !std::isfinite(r.xMax) || !std::isfinite(r.yMin) || !std::isfinite(r.yMax))
        throw Error("LevelSet: the planning region must be bounded");
    Grid &g = impl_->grid;
    g.h = params_.cellSize;
    g.x0 = r.xMin;
    g.y0 = r.yMin;
    const double cx = std::floor((r.xMax - r.xMin) / g.h + 1e-9), cy = std::floor((r.yMax - r.yMin) / g.h + 1e-9);
    if (cx < 4 || cy < 4)
        throw Error("LevelSet: resolution " + text::number(g.h) + " leaves fewer than 4 cells across the region");
    if (cx * cy > 2e8)
        throw Error("LevelSet: resolution " + text::number(g.h) + " gives more than 2e8 grid nodes");
    g.nx = static_cast<int>(cx) + 1;
    g.ny = static_cast<int>(cy) + 1;
    // per node: phi twice, the arrival, the forbidden set and its static part, the step's current (two), its stamp,
    // the update and corridor flags, and the land mask while built
    checkMemory(static_cast<double>(g.size()) * (7 * sizeof(double) + sizeof(std::uint32_t) + 3),
                "the level-set grid (" + std::to_string(g.nx) + " x " + std::to_string(g.ny) + " nodes)",
                "use a coarser resolution");
    impl_->band = params_.band * g.h;
    const double band = impl_->band;

    // Static forbidden set: land (the field's mask at the nodes) and static polygons.
    std::vector<char> land(g.size(), 0);
    bool anyLand = false;
    const double z = ctx_->travel->params().depth;
    for (int j = 0; j < g.ny; ++j)
        for (int i = 0; i < g.nx; ++i)
            if (!ctx_->field->inWater(g.x(i), g.y(j), z))
                land[g.index(i, j)] = anyLand = 1;
    if (anyLand)
        maskDistance(g, land, band, impl_->staticD, params_.clearance);
    else
        impl_->staticD.assign(g.size(), -band);

    std::vector<const Environment *> members, staticOthers;
    if (const auto *fr = dynamic_cast<const ForbiddenRegions *>(ctx_->environment.get()))
        for (const auto &m : fr->regions())
            members.push_back(m.get());
    else if (ctx_->environment)
        members.push_back(ctx_->environment.get());
    for (const Environment *m : members)
    {
        if (const auto *s = dynamic_cast<const StaticRegion *>(m))
        {
            const SparseDistance d = polygonDistance(g, s->polygon(), 0.0, 0.0, band, params_.clearance);
            for (std::size_t k = 0; k < d.nodes.size(); ++k)
                impl_->staticD[d.nodes[k]] = std::max(impl_->staticD[d.nodes[k]], d.d[k]);
        }
        else if (const auto *tz = dynamic_cast<const TimeWindowedZone *>(m))
            impl_->zones.push_back({tz, polygonDistance(g, tz->polygon(), 0.0, 0.0, band, params_.clearance)});
        else if (const auto *iz = dynamic_cast<const IceZone *>(m))
        {
            if (params_.iceForbidden)
                impl_->ice.push_back(iz);
        }
        else if (m->isStatic())
            staticOthers.push_back(m);
        else
            impl_->others.push_back(m);
    }
    // other static regions (keep-off zones, shallow water): their nodes once, like land
    if (!staticOthers.empty())
    {
        std::vector<char> blocked(g.size(), 0);
        bool any = false;
        for (int j = 0; j < g.ny; ++j)
            for (int i = 0; i < g.nx; ++i)
                for (const Environment *e : staticOthers)
                    if (!e->pointFree(g.x(i), g.y(j), 0.0))
                    {
                        blocked[g.index(i, j)] = any = 1;
                        break;
                    }
        if (any)
        {
            std::vector<double> d;
            maskDistance(g, blocked, band, d, params_.clearance);
            for (std::size_t n = 0; n < g.size(); ++n)
                impl_->staticD[n] = std::max(impl_->staticD[n], d[n]);
        }
    }
    bool forbidden = !impl_->zones.empty() || !impl_->ice.empty() || !impl_->others.empty();
    for (double &d : impl_->staticD)
    {
        d = levelset_detail::closedBoundary(d, g.h);
        forbidden = forbidden || d > -band;
        impl_->staticForbidden = impl_->staticForbidden || d > 0.0;
    }
    // the automatic step: long in open water, short near a forbidden set (see LevelSetParams::cfl)
    using levelset_detail::kForbiddenCfl;
    using levelset_detail::kOpenWaterCfl;
    impl_->cfl = params_.cfl > 0.0 ? params_.cfl : forbidden ? kForbiddenCfl : kOpenWaterCfl;
    impl_->reinitEvery = params_.reinitEvery < 0                              ? 0
                         : params_.reinitEvery > 0                            ? params_.reinitEvery
                         : impl_->cfl > 0.5 * (kForbiddenCfl + kOpenWaterCfl) ? levelset_detail::kOpenWaterReinit
                                                                              : levelset_detail::kForbiddenReinit;
}

LevelSetSolver::~LevelSetSolver() = default;

double defaultLevelSetResolution(const GliderContext &ctx)
{
    const Region &r = ctx.region;
    return std::max(r.xMax - r.xMin, r.yMax - r.yMin) / 200.0;
}
} // namespace ompl_glider
