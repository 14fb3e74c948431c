/// @file TveSearchExpansion.cpp
/// @brief The expansion steps of one search of TveSearch (TveSearch::Core, TveSearchCore.h): the examination of an
/// edge (its travel time, the labels, holds before the goal window, departures after a release) and the queue loop
/// of [EichhornRAS] Table 2 (Zermelo pruning, certification of the pruned edges, the unpruned fallback).

#include "TveSearchCore.h"

#include <algorithm>
#include <cmath>

#include "../core/Numbers.h"

namespace ompl_glider
{
namespace
{
/// Angle difference wrapped to [-pi, pi].
double angleDiff(double a, double b)
{
    double d = std::fmod(a - b, 2.0 * kPi);
    if (d > kPi)
        d -= 2.0 * kPi;
    else if (d < -kPi)
        d += 2.0 * kPi;
    return d;
}
} // namespace

/// Travel time of the edge u -> v departing at dep (one CFC; from the edge cache of the phases when there is one).
double TveSearch::Core::edgeTime(Lattice::VertexId u, double ux, double uy, Lattice::VertexId v, double vx, double vy,
                                 double dep)
{
    if (!ts.edgeCache_)
        return travel.travelTime(ux, uy, vx, vy, dep);
    const auto [it, inserted] = ts.edgeCache_->try_emplace(EdgeKey{u, v, dep}, 0.0);
    if (inserted)
        it->second = travel.travelTime(ux, uy, vx, vy, dep);
    return it->second;
}

/// Improves v: arrival dv through u, departing from u at dep (-inf: on arrival); queued unless the goal cannot be
/// reached from v.
void TveSearch::Core::label(Lattice::VertexId u, Lattice::VertexId v, double dv, double dep)
{
    Label &lv = ts.labels_.ref(v);
    if (lv.d == kInf)
        ts.reached_.push_back(v);
    lv.d = dv;
    lv.pi = u;
    lv.dep = dep;
    const double hv = h(v);
    if (hv < kInf) // +inf: the goal cannot be reached from v even with the optimistic bounds
        Q.push({dv + hv, dv, v});
}

/// Holding at u over [du, tw]: |c| < V there (a superset of the motion validator's samples) and u free.
bool TveSearch::Core::canWait(double ux, double uy, double du, double tw) const
{
    return ctx.canHold(ux, uy, du, tw, holdStep, 4) && (!env || env->legFree(ux, uy, du, ux, uy, tw));
}

/// Examines the edge u -> v leaving at du (one CFC): true when its travel time is finite; improves v when the arrival
/// is earlier than d[v], inside the window and free.
bool TveSearch::Core::relax(Lattice::VertexId u, double ux, double uy, double du, Lattice::VertexId v)
{
    if (!inWater(v))
        return false;
    const double vx = lattice.x(v), vy = lattice.y(v);
    if (bounds && boundSkip(u, du, v))
    {
        ++res.boundSkips;
        return true;
    }
    const double w = edgeTime(u, ux, uy, v, vx, vy, du);
    if (!std::isfinite(w))
        return false;
    const double dv = du + w;
    if (options.waiting && v == g && goalWindow)
    {
        // goal window: an arrival counts inside [arriveNotBefore, arriveNotAfter] (TveOptions::waiting)
        if (dv > ctx.arriveNotAfter)
            return true;
        if (dv < ctx.arriveNotBefore && !(ctx.canHold(gx, gy, dv, ctx.arriveNotBefore, holdStep, 4) &&
                                          (!env || env->legFree(gx, gy, dv, gx, gy, ctx.arriveNotBefore))))
        {
            holdBeforeGoal(u, ux, uy, du, v, vx, vy);
            return true;
        }
    }
    if (!(dv < dist(v)) || dv > tEnd)
        return true; // no improvement, or later than the planning window
    if (env && (!env->pointFree(vx, vy, dv) || !env->legFree(ux, uy, du, vx, vy, dv)))
    {
        if (options.waiting && !releases.empty())
            departAfterRelease(u, ux, uy, du, v, vx, vy);
        return true;
    }
    label(u, v, dv, -kInf);
    return true;
}

/// The edge u -> v into the goal arrives before the goal window opens and the goal cannot be held: hold at u so that
/// the edge arrives at the window's begin (bisection on the departure; arrival non-decreasing in it, FIFO).
void TveSearch::Core::holdBeforeGoal(Lattice::VertexId u, double ux, double uy, double du, Lattice::VertexId v,
                                     double vx, double vy)
{
    const double B = ctx.arriveNotBefore;
    if (!(B < dist(v)) || B > tEnd)
        return;
    double lo = du, hi = B;
    double hiArr = hi + edgeTime(u, ux, uy, v, vx, vy, hi);
    if (!std::isfinite(hiArr))
        return;
    for (int it = 0; it < 50 && hiArr > B * (1.0 + 1e-12) + 1e-12; ++it)
    {
        const double mid = 0.5 * (lo + hi);
        const double a = mid + edgeTime(u, ux, uy, v, vx, vy, mid);
        if (std::isfinite(a) && a >= B)
        {
            hi = mid;
            hiArr = a;
        }
        else
            lo = mid;
    }
    if (!(hiArr < dist(v)) || hiArr > tEnd || hiArr > ctx.arriveNotAfter || !canWait(ux, uy, du, hi))
        return;
    if (env && (!env->pointFree(vx, vy, hiArr) || !env->legFree(ux, uy, hi, vx, vy, hiArr)))
        return;
    label(u, v, hiArr, hi);
}

/// The edge u -> v leaving at du is blocked by the environment: a waiting edge departing just after a release time
/// (the end of a blocking window), the first that frees the leg (later ones arrive no earlier where the field is
/// FIFO).
void TveSearch::Core::departAfterRelease(Lattice::VertexId u, double ux, double uy, double du, Lattice::VertexId v,
                                         double vx, double vy)
{
    for (const double r : releases)
    {
        const double tw = r + 1e-9 * std::max(1.0, std::abs(r));
        if (tw <= du)
            continue;
        if (tw > tEnd || !(tw < dist(v)) || !canWait(ux, uy, du, tw))
            break; // later departures cannot improve v, or the glider cannot hold that long
        const double ww = edgeTime(u, ux, uy, v, vx, vy, tw);
        if (!std::isfinite(ww))
            continue;
        const double dw = tw + ww;
        if (dw > tEnd || !(dw < dist(v)))
            break;
        if (env->pointFree(vx, vy, dw) && env->legFree(ux, uy, tw, vx, vy, dw))
        {
            if (v == g && goalWindow && dw > ctx.arriveNotAfter)
                break;
            label(u, v, dw, tw);
            break;
        }
    }
}

/// The queue loop ([EichhornRAS] Table 2): the goal vertex when it is extracted, kNone when the queue runs empty or
/// the termination callback fires (res.outcome Terminated).
///
/// Certification (TveOptions::certifyTolerance): pruned edges are deferred, not dropped, each with the lower
/// bound key = d[u] + (edge bound) + h(v) of the queue key v would get through it (h = the queue's heuristic, 0
/// without A*). A deferred edge is examined as soon as its key, inflated by (1 + tol) from t0, is not above the
/// queue's smallest key, i.e. in key order interleaved with the queue. With tol = 0 and a consistent heuristic
/// (and edge bounds consistent with it) every vertex is extracted with its final label, as in A* without
/// pruning: the search returns the fixpoint d(v) = min_u d(u) + w(u, v, d(u)) that TVE computes (unique for
/// positive edge times), only without the CFC of the deferred edges whose key exceeds the goal's arrival.
/// (The earlier rule examined deferred edges only after the goal's first extraction; a vertex could then be
/// improved after its successors had been labelled from its old arrival time, and the returned arrival could
/// differ from TVE's where the field is not FIFO, e.g. random pair 9 of bench_search, 16 % below TVE's.)
Lattice::VertexId TveSearch::Core::search()
{
    for (;;)
    {
        if (certify && !deferred.empty() &&
            (Q.empty() || t0 + (deferred.top().key - t0) * (1.0 + options.certifyTolerance) <= Q.top().key))
        {
            examineDeferred();
            continue;
        }
        if (Q.empty())
        {
            if (restartUnpruned())
                continue;
            return Lattice::kNone;
        }
        const QueueEntry e = Q.top();
        Q.pop();
        const Lattice::VertexId u = e.v;
        if (e.d != dist(u))
            continue; // stale entry (u was improved after this push)
        if (u == g)
            return u;
        if (!options.reopen)
        {
            Label &lu = ts.labels_.ref(u);
            if (lu.expanded)
                continue; // expanded once already (TveOptions::reopen)
            lu.expanded = true;
        }
        ++res.expansions;
        if (res.expansions % checkEvery == 0 && terminated())
        {
            res.outcome = TveOutcome::Terminated;
            return Lattice::kNone;
        }
        expand(u);
    }
}

/// Examines the deferred edge with the smallest key (certification).
void TveSearch::Core::examineDeferred()
{
    const DeferredEdge de = deferred.top();
    deferred.pop();
    // stale (u improved and re-expanded since), or cannot improve v even at the bound
    if (de.du != dist(de.u) || !(de.du + edgeBound(de.u, de.v) < dist(de.v)))
        return;
    ++res.reopenedEdges;
    relax(de.u, lattice.x(de.u), lattice.y(de.u), de.du, de.v);
}

/// The pruned search could not reach the goal: continue with the full neighbourhoods of the vertices whose expansion
/// pruned edges (TveOptions::unprunedFallback). False when there is nothing to continue with.
bool TveSearch::Core::restartUnpruned()
{
    if (!(pruning && options.unprunedFallback && !prunedAt.empty()))
        return false;
    pruning = false;
    res.fallbackUsed = true;
    for (Lattice::VertexId v : prunedAt)
    {
        ts.labels_.ref(v).expanded = false; // expanded again, with every edge
        if (h(v) < kInf)
            Q.push({dist(v) + h(v), dist(v), v});
    }
    prunedAt.clear();
    return true;
}

/// Zermelo pruning at u ([EichhornRAS] Sec. 2.2.2): phi_opt predicted by CALC-OPTDIR from u's predecessor edge,
/// extrapolated and widened with the predicted turn (TveOptions); no course at the start, near the goal
/// (goalRadius), where the prediction fails or is unreliable, and without pruning.
tve_detail::Cone TveSearch::Core::predictCone(Lattice::VertexId u, double ux, double uy, double du)
{
    Cone cone{std::nullopt, options.deltaPhiMax};
    if (!pruning || u == s || parent(u) == Lattice::kNone ||
        (options.goalRadius > 0.0 && std::hypot(ux - gx, uy - gy) <= options.goalRadius))
        return cone;
    const Lattice::VertexId p = parent(u);
    cone.phiOpt = ts.calcOptimalCourse(lattice.x(p), lattice.y(p), dist(p), ux, uy, du, options.zermeloSteps);
    if (cone.phiOpt)
    {
        const double edge = std::atan2(uy - lattice.y(p), ux - lattice.x(p));
        const double turn = angleDiff(*cone.phiOpt, edge);
        *cone.phiOpt += options.courseExtrapolation * turn;
        cone.halfWidth = options.deltaPhiMax + options.turnWidening * std::abs(turn);
        if (std::abs(turn) > options.reliableTurn)
            cone.phiOpt.reset(); // unreliable prediction: examine every successor
    }
    return cone;
}

/// Expands u: examines its successors inside the Zermelo cone, defers (certification) or drops the others.
void TveSearch::Core::expand(Lattice::VertexId u)
{
    const double du = dist(u);
    const double ux = lattice.x(u), uy = lattice.y(u);
    const Cone cone = predictCone(u, ux, uy, du);
    bool prunedHere = false;
    bool feasibleInCone = false; // some examined edge had a finite travel time
    // pass 0: the cone around phi_opt (everything without pruning); pass 1: the rest, only when the cone was a
    // dead end (options.deadEndFallback).
    for (int pass = 0; pass < 2; ++pass)
    {
        if (pass == 1 && (!prunedHere || feasibleInCone || !options.deadEndFallback))
            break;
        lattice.forEachSuccessor(u, [&](Lattice::VertexId v) {
            if (!(du < dist(v)))
                return; // d[u] >= d[v]: the edge cannot improve v ([EichhornRAS] Table 1, difference 2)
            const double vx = lattice.x(v), vy = lattice.y(v);
            const bool inCone = !cone.phiOpt || (options.neverPruneGoal && v == g) ||
                                std::abs(angleDiff(*cone.phiOpt, std::atan2(vy - uy, vx - ux))) <= cone.halfWidth;
            if (pass == 0 && !inCone)
            {
                ++res.prunedEdges;
                prunedHere = true;
                if (certify)
                {
                    // a lower bound of the queue key v would get through u -> v
                    const double key = du + edgeBound(u, v) + h(v);
                    if (key < kInf)
                        deferred.push({key, du, u, v});
                }
                return;
            }
            if (pass == 1 && inCone)
                return; // examined in pass 0
            if (relax(u, ux, uy, du, v))
                feasibleInCone = true;
        });
        if (pass == 1)
        {
            ++res.deadEnds;
            prunedHere = false; // everything examined now
        }
    }
    if (prunedHere)
        prunedAt.push_back(u);
}
} // namespace ompl_glider
