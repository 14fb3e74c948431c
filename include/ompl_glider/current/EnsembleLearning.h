#pragma once
/// @file EnsembleLearning.h
/// @brief The forecast a glider's depth-averaged currents (DAC) make: for one forecast, the forecast corrected by
/// them (CorrectedField); for an ensemble, its members weighed by how well each agrees with the DAC, their weighted
/// mean updated from the members' anomalies (an ensemble Kalman update solved in the members' space, [EvensenEnKF]:
/// a correction that can move a feature the members place differently, [RavelaFCA]), and what is left corrected by
/// optimal interpolation.

#include <memory>
#include <vector>

#include "ompl_glider/current/CorrectedField.h"
#include "ompl_glider/current/CurrentField.h"

namespace ompl_glider
{
/// @brief What the DAC said of one member.
struct MemberScore
{
    double weight{0.0};        ///< its likelihood given the DAC, normalised over the members (sum 1)
    double rmsInnovation{0.0}; ///< RMS |DAC - member| over the DAC that weighed it (field units)
    double coefficient{0.0};   ///< its coefficient in the forecast to plan on (sum 1; may be negative)
};

/// @brief The forecast to plan on after the DAC, and how it was made.
struct LearnedForecast
{
    std::shared_ptr<const CurrentField> field; ///< the forecast to plan on
    std::vector<MemberScore> members;          ///< one per ensemble member (empty: one forecast)
    std::size_t weighedBy{0};                  ///< DAC that weighed the members
    CorrectionSummary correction;              ///< the optimal interpolation of what is left
};

/// At most this many of the most recent DAC weigh and update the members.
constexpr std::size_t kMaxWeighing = 200;

/// @brief The forecast @p observations make of @p forecast (with @p members: an ensemble whose mean @p forecast is)
/// with the correction's @p params (params.dacError: the DAC's error, the likelihood's observation error). Without
/// members, or without a DAC the members can be compared with: the forecast corrected (CorrectedField), the members
/// weighed equally.
LearnedForecast learnForecast(const std::shared_ptr<const CurrentField> &forecast,
                              const std::vector<std::shared_ptr<const CurrentField>> &members,
                              const std::vector<DacObservation> &observations, const CorrectionParams &params);

/// @brief learnForecast() during a flight, as the DAC arrive: the scales not given are estimated again only once the
/// DAC have grown by half since the last estimate (an estimate costs a few hundred factorisations), and held in
/// between (the held-out check's outcome with them: where the priors stood, the priors are held); the innovations' mean
/// (itself judged on the later DAC, CorrectionFit.h), the members' weights and the interpolation are made anew at every
/// call.
class FlightLearning
{
public:
    FlightLearning(std::shared_ptr<const CurrentField> forecast,
                   std::vector<std::shared_ptr<const CurrentField>> members, CorrectionParams params);
    /// @brief The forecast @p measured make.
    std::shared_ptr<const CurrentField> operator()(const std::vector<DacObservation> &measured);
    /// @brief What the last call made.
    const LearnedForecast &last() const { return last_; }

private:
    std::shared_ptr<const CurrentField> forecast_;
    std::vector<std::shared_ptr<const CurrentField>> members_;
    CorrectionParams params_;
    CorrectionParams estimated_; // the last estimate (valid when estimatedAt_ > 0)
    std::size_t estimatedAt_{0}; // the DAC it was made from
    LearnedForecast last_;
};
} // namespace ompl_glider
