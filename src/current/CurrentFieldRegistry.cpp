#include "ompl_glider/current/CurrentFieldRegistry.h"

#include "ompl_glider/Config.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/current/DoubleGyre.h"
#include "ompl_glider/current/LinearShear.h"
#include "ompl_glider/current/MeanderingJet.h"
#if OMPL_GLIDER_WITH_NETCDF
#include "ompl_glider/current/GriddedCurrents.h"
#endif
#include "ompl_glider/current/RankineVortex.h"
#include "ompl_glider/current/UniformCurrent.h"

namespace ompl_glider
{
namespace
{
#if !OMPL_GLIDER_WITH_NETCDF
/// A build without NetCDF: the kind is known, and says why it cannot be read.
class NoNetCdfSource final : public GriddedSource
{
    [[noreturn]] static void refuse()
    {
        throw Error("this build of ompl_glider has no NetCDF support (OMPL_GLIDER_WITH_NETCDF=OFF)");
    }

public:
    bool geographic(const ForecastRequest &) const override { refuse(); }
    ForecastExtent extent(const ForecastRequest &) const override { refuse(); }
    ForecastTimeAxis timeAxis(const ForecastRequest &) const override { refuse(); }
    LoadedForecast load(const ForecastRequest &) const override { refuse(); }
};

std::shared_ptr<const GriddedSource> griddedForecastSource()
{
    static const auto source = std::make_shared<const NoNetCdfSource>();
    return source;
}
#endif

/// The registry: the built-in kinds, then those of registerCurrentFieldKind(); a deque, so that an entry never moves.
std::deque<CurrentFieldKind> &kinds()
{
    using P = std::map<std::string, double>;
    static std::deque<CurrentFieldKind> kinds = [] {
        const MeanderingJetParams j;
        std::deque<CurrentFieldKind> k;
        k.push_back(
            {"meandering_jet",
             "meandering jet (Gulf Stream model)",
             {{"B0", j.B0}, {"epsilon", j.epsilon}, {"omega", j.omega}, {"theta", j.theta}, {"k", j.k}, {"c", j.c}},
             [](const P &p) {
                 MeanderingJetParams q;
                 q.B0 = p.at("B0");
                 q.epsilon = p.at("epsilon");
                 q.omega = p.at("omega");
                 q.theta = p.at("theta");
                 q.k = p.at("k");
                 q.c = p.at("c");
                 return std::make_shared<MeanderingJet>(q);
             },
             nullptr});
        k.push_back({"uniform",
                     "uniform current (u, v)",
                     {{"u", 0.0}, {"v", 0.0}},
                     [](const P &p) { return std::make_shared<UniformCurrent>(p.at("u"), p.at("v")); },
                     nullptr});
        k.push_back({"linear_shear",
                     "linear shear u = a y (Zermelo's problem)",
                     {{"a", -1.0}},
                     [](const P &p) { return std::make_shared<LinearShear>(p.at("a")); },
                     nullptr});
        k.push_back({"double_gyre",
                     "double gyre on [0, 2 length] x [0, length], steady, or time-dependent when epsilon and omega "
                     "are not 0 ([ShaddenLCS])",
                     {{"amplitude", 0.1}, {"length", 1.0}, {"epsilon", 0.0}, {"omega", 0.0}},
                     [](const P &p) {
                         return std::make_shared<DoubleGyre>(p.at("amplitude"), p.at("length"), p.at("epsilon"),
                                                             p.at("omega"));
                     },
                     nullptr});
        const RankineVortexParams rv;
        k.push_back({"rankine_vortex",
                     "Rankine vortex centred at (x0, y0), core radius radius, azimuthal speed vmax at the core "
                     "radius (counter-clockwise for vmax > 0), in a uniform stream (u, v) ([LollaLevelSet])",
                     {{"x0", rv.x0}, {"y0", rv.y0}, {"radius", rv.radius}, {"vmax", rv.vmax}, {"u", rv.u}, {"v", rv.v}},
                     [](const P &p) {
                         RankineVortexParams q;
                         q.x0 = p.at("x0");
                         q.y0 = p.at("y0");
                         q.radius = p.at("radius");
                         q.vmax = p.at("vmax");
                         q.u = p.at("u");
                         q.v = p.at("v");
                         return std::make_shared<RankineVortex>(q);
                     },
                     nullptr});
        k.push_back({"gridded",
                     "gridded forecast read from NetCDF files, OPeNDAP datasets, Zarr stores or GRIB files",
                     {},
                     nullptr,
                     griddedForecastSource()});
        return k;
    }();
    return kinds;
}

/// The aliases: (alias, the kind's name), in the order they were added; the built-in "netcdf" for `gridded`.
std::vector<std::pair<std::string, std::string>> &aliases()
{
    static std::vector<std::pair<std::string, std::string>> list{{"netcdf", "gridded"}};
    return list;
}
} // namespace

const std::deque<CurrentFieldKind> &currentFieldKinds()
{
    return kinds();
}

void registerCurrentFieldKind(CurrentFieldKind kind)
{
    if (kind.name.empty() || !kind.make == !kind.source)
        throw Error("registerCurrentFieldKind: a kind needs a name and either a make function (an analytic flow) "
                    "or a source (a gridded forecast)");
    if (findCurrentFieldKind(kind.name))
        throw Error("registerCurrentFieldKind: the name '" + kind.name + "' is taken");
    if (kind.source && !kind.parameters.empty())
        throw Error("registerCurrentFieldKind: a gridded kind ('" + kind.name + "') takes a file, not parameters");
    kinds().push_back(std::move(kind));
}

const CurrentFieldKind *findCurrentFieldKind(const std::string &name)
{
    for (const CurrentFieldKind &k : currentFieldKinds())
        if (k.name == name)
            return &k;
    for (const auto &[alias, kind] : aliases())
        if (alias == name)
            for (const CurrentFieldKind &k : currentFieldKinds())
                if (k.name == kind)
                    return &k;
    return nullptr;
}

void addCurrentFieldKindAlias(const std::string &alias, const std::string &name)
{
    const CurrentFieldKind *kind = findCurrentFieldKind(name);
    if (!kind)
        throw Error("addCurrentFieldKindAlias: no current kind '" + name + "'");
    if (alias.empty() || findCurrentFieldKind(alias))
        throw Error("addCurrentFieldKindAlias: the alias '" + alias + "' is " + (alias.empty() ? "empty" : "taken"));
    aliases().emplace_back(alias, kind->name);
}

std::vector<std::string> currentFieldKindAliases(const CurrentFieldKind &kind)
{
    std::vector<std::string> out;
    for (const auto &[alias, name] : aliases())
        if (name == kind.name)
            out.push_back(alias);
    return out;
}

bool isGriddedKind(const std::string &name)
{
    const CurrentFieldKind *kind = findCurrentFieldKind(name);
    return kind && kind->gridded();
}

std::vector<std::string> currentFieldKindNames()
{
    std::vector<std::string> out;
    for (const CurrentFieldKind &k : currentFieldKinds())
    {
        out.push_back(k.name);
        for (const std::string &alias : currentFieldKindAliases(k))
            out.push_back(alias);
    }
    return out;
}

std::string currentFieldKindList(const std::string &separator)
{
    std::string out;
    for (const CurrentFieldKind &k : currentFieldKinds())
        out += (out.empty() ? "" : separator) + k.name;
    return out;
}

std::string griddedKindList(const std::string &separator)
{
    std::string out;
    for (const CurrentFieldKind &k : currentFieldKinds())
        if (k.gridded())
            out += (out.empty() ? "" : separator) + k.name;
    return out;
}

bool hasParameter(const CurrentFieldKind &kind, const std::string &name)
{
    for (const auto &[key, value] : kind.parameters)
        if (key == name)
            return true;
    return false;
}

std::string parameterNameList(const CurrentFieldKind &kind)
{
    std::string out;
    for (const auto &[key, value] : kind.parameters)
        out += (out.empty() ? "" : ", ") + key;
    return out;
}

std::shared_ptr<const CurrentField> makeAnalyticField(const std::string &name,
                                                      const std::map<std::string, double> &parameters)
{
    const CurrentFieldKind *kind = findCurrentFieldKind(name);
    if (!kind)
        throw Error("unknown current type '" + name + "' (expected one of " + currentFieldKindList() + ")");
    if (kind->gridded())
        throw Error("current type '" + name + "' is read from a file, not made from parameters");
    std::map<std::string, double> full;
    for (const auto &[key, value] : kind->parameters)
        full[key] = value;
    for (const auto &[key, value] : parameters)
    {
        if (!hasParameter(*kind, key))
            throw Error("current type '" + name + "' has no parameter '" + key + "' (expected " +
                        parameterNameList(*kind) + ")");
        full[key] = value;
    }
    return kind->make(full);
}
} // namespace ompl_glider
