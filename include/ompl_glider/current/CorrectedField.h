#pragma once
/// @file CorrectedField.h
/// @brief A forecast corrected by a glider's depth-averaged currents (DAC) by optimal interpolation ([BrethertonOI]):
/// innovations d_i = DAC_i - F(x_i, t_i) (F averaged over the glider's depth range), spread with a space-time Gaussian
/// covariance C = exp(-r^2 / (2 L^2)) exp(-dt^2 / (2 T^2)) (the forecast error variance s_f^2 factored out), weights
/// alpha = (C_obs,obs + (s_o / s_f)^2 I)^-1 d, and F'(x, t) = F(x, t) + sum_i C(x, t; x_i, t_i) alpha_i. Far from the
/// observations and long after the last one F' = F. A current field like any other: every planner, the level set,
/// isochrones and the execution fly it.
///
/// Learning from the data (CorrectionParams::learn, current/CorrectionFit.h): with enough DAC the scales not given
/// are estimated by maximising the innovations' marginal likelihood ([RasmussenGP] Eq. 5.8), and a mean of the
/// innovations (a bias, and the main tidal constituents where the record resolves them, [MerckelbachDAC]) is carried
/// ahead with long scales of its own (InnovationMean); the optimal interpolation then spreads what is left.

#include <cstddef>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "ompl_glider/current/CurrentField.h"

namespace ompl_glider
{
class GriddedCurrentField;

/// @brief One depth-averaged current measured by a glider, in the planning frame.
struct DacObservation
{
    double t{0.0}; ///< time (field units): the middle of the dive it averages
    Point2 at;     ///< where (planning frame): the middle of the dive
    Velocity dac;  ///< the depth-averaged current (field units)
    /// The forecast averaged as the DAC was (along the same dive: a simulated glider knows its track); unset: the
    /// forecast at (at, t) over the depth range (CorrectedField::depthAveraged())
    std::optional<Velocity> forecast;
    /// The dive's own depth range (m, positive down) where its file gives it: the forecast is averaged over it; NaN:
    /// over the correction's range (CorrectionParams::depthTop, depthBottom)
    double depthTop{std::numeric_limits<double>::quiet_NaN()};
    double depthBottom{std::numeric_limits<double>::quiet_NaN()}; ///< see depthTop
};

/// @brief The correction's parameters (field units).
struct CorrectionParams
{
    double lengthScale{20000.0}; ///< L: the distance over which forecast errors are alike (20 km for a forecast)
    double timeScale{86400.0};   ///< T: the time over which they persist (1 day for a forecast)
    /// s_o / s_f: observation error over forecast error (> 0); 0.2: a DAC is good to about 2 cm/s, a forecast's current
    /// to about 10 cm/s
    double errorRatio{0.2};
    double depthTop{0.0};              ///< the glider's depth range, averaged over to compare with a DAC (m)
    double depthBottom{0.0};           ///< see depthTop (equal: the forecast at that depth)
    std::size_t maxObservations{2000}; ///< the most recent ones kept (the system is solved once, O(n^3))
    /// Learn from the DAC: with at least minLearn of them and innovations not all zero, estimate the scales not given
    /// (lengthGiven, timeGiven, ratioGiven false) and the innovations' mean (bias, tides); false: the values above
    bool learn{false};
    bool lengthGiven{true}; ///< lengthScale was given (kept); false: a prior, estimated when learning
    bool timeGiven{true};   ///< see lengthGiven
    bool ratioGiven{true};  ///< see lengthGiven
    /// Where the priors of the scales not given come from, in the report's words ("" : the defaults; with forecast
    /// runs, their spread: ForecastRuns.h's runSpread())
    std::string priorSource{};
    std::size_t minLearn{6}; ///< fewer DAC than this: the priors stand and no mean is fitted
    /// The DAC's own error (field units; > 0 when learning): the observation error is never estimated below it
    double dacError{0.0};
    /// Seconds per field time unit, to fit the tides (whose periods are in hours); 0: the time unit is unknown, no
    /// tidal fit
    double secondsPerTimeUnit{0.0};
    /// With more superobservations than this, the interpolated correction is sampled once on a grid of a quarter of
    /// the scales (bicubic in space, linear in time) and read from it: a velocity then costs the same whatever the
    /// number of DAC. At or below it, the exact sum over the superobservations.
    std::size_t sampleAbove{24};
};

/// @brief The innovations' large-scale mean, carried ahead of the glider: a bias and tidal constituents, fading with
/// long scales of their own outside the data's box and time span.
struct InnovationMean
{
    /// One tidal constituent: cos(omega (t - tRef)) * cosine + sin(omega (t - tRef)) * sine, per component.
    struct Constituent
    {
        std::string name;  ///< "M2", "S2", "K1", "O1"
        double omega{0.0}; ///< angular frequency, radians per field time unit
        Velocity cosine;   ///< the coefficients of the cosine (u, v)
        Velocity sine;     ///< the coefficients of the sine
        /// @brief The amplitude of component u (v: false), field units.
        double amplitude(bool u) const;
        /// @brief The phase of component u (v: false): the angle phi with c cos(w t - phi), radians.
        double phase(bool u) const;
    };
    Velocity bias;                                     ///< the mean of the innovations (field units)
    std::vector<Constituent> tides;                    ///< fitted constituents (empty: none)
    double tRef{0.0};                                  ///< the tides' time origin
    double tBegin{0.0}, tEnd{0.0};                     ///< the span of the DAC it was fitted to
    double xMin{0.0}, xMax{0.0}, yMin{0.0}, yMax{0.0}; ///< their box
    double lengthScale{0.0};                           ///< fading outside the box (planning units; 0: no mean)
    double timeScale{0.0};                             ///< fading outside the span (field time units)
    /// @brief Whether there is a mean to add.
    bool active() const { return lengthScale > 0.0; }
    /// @brief The mean at (x, y, t), and with @p j its spatial derivatives added.
    Velocity at(double x, double y, double t, Jacobian *j = nullptr) const;
    /// @brief A bound of |u| and |v| of the mean anywhere.
    void bound(double &u, double &v) const;
};
/// @brief The learned correction judged on DAC not used to fit it (CorrectionFit.h): the scales and the mean estimated
/// from the earlier DAC predict the later ones (forecast plus correction at their time and place, from the earlier DAC
/// alone), against the priors (the scales as given or by default, no mean: what learning off uses). What predicted
/// best is kept for the correction, estimated again from all the DAC; the priors stand on a tie.
struct HeldOutCheck
{
    std::size_t fitted{0}; ///< the earlier DAC the check's estimate was fitted to
    std::size_t scored{0}; ///< the later DAC it was scored on (0: too few DAC to judge; the priors stand)
    /// The RMS error of each candidate's prediction of the scored DAC (field units): the priors; the priors' scales
    /// with the learned mean; the learned scales without a mean; the learned scales and mean
    double priorError{0.0}, meanError{0.0}, scalesError{0.0}, learnedError{0.0};
    double lengthScale{0.0}, timeScale{0.0}, errorRatio{0.0}; ///< the scales estimated from the earlier DAC
    bool scalesKept{false}; ///< the learned scales are the correction's (false: the priors stand)
    bool meanKept{false};   ///< the learned mean (bias, tides) is the correction's
};

/// @brief What the correction used and what it did.
struct CorrectionSummary
{
    std::size_t given{0};           ///< observations given
    std::size_t used{0};            ///< used in the correction
    std::size_t outsideForecast{0}; ///< rejected: outside the forecast's time, on land or off its grid
    std::size_t older{0};           ///< rejected: older than the maxObservations most recent
    std::size_t notFinite{0};       ///< rejected: a coordinate or a component not finite
    double rmsBefore{0.0};          ///< RMS |d_i| against the forecast (field units)
    double rmsAfter{0.0};           ///< RMS |DAC_i - F'(x_i, t_i)| against the corrected field
    /// The mean of the innovations d_i = DAC_i - F(x_i, t_i) of the DAC used (field units): what the glider measured
    /// more than the forecast, on average (0 without DAC)
    Velocity meanInnovation;
    double firstUsed{0.0}, lastUsed{0.0}; ///< the times of the oldest and newest DAC used (field time)
    CorrectionParams params;              ///< the parameters as used (estimated ones in place of their priors)
    /// Where L, T and the ratio came from: "given", "default", or "estimated from N DAC"
    std::string lengthSource, timeSource, ratioSource;
    std::size_t learnedFrom{0}; ///< DAC the estimate used (0: nothing was estimated)
    /// ln of the marginal likelihood at the estimate minus at the priors (>= 0; 0: nothing was estimated)
    double likelihoodGain{0.0};
    InnovationMean mean;  ///< the innovations' mean carried ahead (inactive: none)
    HeldOutCheck heldOut; ///< the estimate judged on later DAC (learnedFrom > 0)
};

/// @brief @p field's current averaged over the depths @p top to @p bottom (m; equal: the current at that depth) at
/// (x, y, t): what a DAC measured there is compared with.
Velocity depthAveragedCurrent(const CurrentField &field, double x, double y, double t, double top, double bottom);

/// @brief What the DAC @p o is compared with in @p field: its own forecast where it carries one, else the current
/// averaged over its dive's depth range where it has one, else over @p params' range.
Velocity forecastAtDac(const CurrentField &field, const DacObservation &o, const CorrectionParams &params);

/// @brief The forecast @p base corrected by @p observations (see the file comment).
class CorrectedField : public CurrentField
{
public:
    /// Past this many length or time scales an observation's Gaussian weight is below exp(-12.5) (4e-6): left out.
    static constexpr double kCutoff = 5.0;

    /// @throws Error for a null base, or scales / ratio not finite and > 0.
    CorrectedField(std::shared_ptr<const CurrentField> base, const std::vector<DacObservation> &observations,
                   CorrectionParams params = {});

    /// @brief The base forecast averaged over the glider's depth range at (x, y, t).
    Velocity depthAveraged(double x, double y, double t) const;
    /// @brief What the correction used and did.
    const CorrectionSummary &summary() const { return summary_; }
    /// @brief The correction alone at (x, y, t): F' - F.
    Velocity correction(double x, double y, double t) const;

    /// @brief The corrected current at one point by the exact sum over the superobservations, without sampling the
    /// grid (sampled at the first velocity() or jacobian() that needs it).
    Velocity velocityOnce(double x, double y, double z, double t) const override;

    double maxSpeed(const Region &region) const override;
    /// @brief The forecast's local bounds widened by the correction's largest reach over the region.
    bool velocityBounds(const Region &region, double &uMin, double &uMax, double &vMin, double &vMax) const override;
    bool hasVelocityBounds() const override { return base_->hasVelocityBounds(); }
    bool inWater(double x, double y, double z) const override { return base_->inWater(x, y, z); }
    bool segmentInWater(double x1, double y1, double x2, double y2, double z) const override
    {
        return base_->segmentInWater(x1, y1, x2, y2, z);
    }
    std::vector<Segment2> landBoundary(double z) const override { return base_->landBoundary(z); }
    double timeBegin() const override { return base_->timeBegin(); }
    double timeEnd() const override { return base_->timeEnd(); }
    const FieldGrid *grid() const override { return base_->grid(); }
    std::string name() const override;

protected:
    Velocity evaluate(double x, double y, double z, double t) const override;
    Jacobian evaluateJacobian(double x, double y, double z, double t) const override;

private:
    /// The sums of |alpha_u| and |alpha_v| (and of |alpha|) over the observations that reach @p region, each at most
    /// what the data support (uLow_ ... vHigh_), plus the mean's bound.
    void reach(const Region &region, double &su, double &sv, double &s) const;
    /// Adds the correction (and, with @p j, its Jacobian) at (x, y, t): from the sampled grid where there is one,
    /// else (or when @p exact) the sum over the superobservations.
    void addCorrection(double x, double y, double t, Velocity &c, Jacobian *j, bool exact = false) const;

    std::shared_ptr<const CurrentField> base_;
    CorrectionParams params_;
    /// A superobservation: the DAC of one cell of an eighth of the scales, averaged (their mean time and place).
    struct Node
    {
        double t;
        Point2 at;
    };
    std::vector<DacObservation> used_;    // by time
    std::vector<Node> nodes_;             // the superobservations, by time
    std::vector<double> alphaU_, alphaV_; // their weights (innovations less their mean)
    /// The interpolated part sampled on a grid (CorrectionParams::sampleAbove; null: the exact sum), and the box
    /// and span it covers (the superobservations' extent and the cut-off beyond it: zero outside)
    /// It is made at the first query that reads it (a glider's heading at a surfacing, velocityOnce(), does not: a
    /// correction made anew at every surfacing is sampled only when a plan is made on it).
    mutable std::shared_ptr<const GriddedCurrentField> sampled_;
    mutable double sampleXMin_{0.0}, sampleXMax_{0.0}, sampleYMin_{0.0}, sampleYMax_{0.0}, sampleTMin_{0.0},
        sampleTMax_{0.0};
    mutable std::once_flag sampleOnce_;
    /// Samples the interpolated part on its grid (sampled_), when there are more superobservations than
    /// CorrectionParams::sampleAbove and the grid stays within a few million nodes.
    void sample() const;
    /// The sampled grid (made at the first call; null: the exact sum).
    const GriddedCurrentField *sampledGrid() const;
    /// What the data support: the interpolated part of the correction stays within the range of the superobservations'
    /// innovations (less their mean) and zero, per component, however ill-conditioned their system
    double uLow_{0.0}, uHigh_{0.0}, vLow_{0.0}, vHigh_{0.0};
    CorrectionSummary summary_;
};
} // namespace ompl_glider
