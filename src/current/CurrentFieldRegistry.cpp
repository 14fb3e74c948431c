#include "ompl_glider/current/CurrentFieldRegistry.h"

#include "ompl_glider/Exception.h"
#include "ompl_glider/current/DoubleGyre.h"
#include "ompl_glider/current/LinearShear.h"
#include "ompl_glider/current/MeanderingJet.h"
#include "ompl_glider/current/UniformCurrent.h"

namespace ompl_glider
{
const std::vector<CurrentFieldKind> &currentFieldKinds()
{
    using P = std::map<std::string, double>;
    static const std::vector<CurrentFieldKind> kinds = [] {
        const MeanderingJetParams j;
        std::vector<CurrentFieldKind> k;
        k.push_back({"meandering_jet",
                     "meandering jet (Gulf Stream model)",
                     {{"B0", j.B0}, {"epsilon", j.epsilon}, {"omega", j.omega}, {"theta", j.theta}, {"k", j.k},
                      {"c", j.c}},
                     false,
                     [](const P &p) {
                         MeanderingJetParams q;
                         q.B0 = p.at("B0");
                         q.epsilon = p.at("epsilon");
                         q.omega = p.at("omega");
                         q.theta = p.at("theta");
                         q.k = p.at("k");
                         q.c = p.at("c");
                         return std::make_shared<MeanderingJet>(q);
                     }});
        k.push_back({"uniform", "uniform current (u, v)", {{"u", 0.0}, {"v", 0.0}}, false,
                     [](const P &p) { return std::make_shared<UniformCurrent>(p.at("u"), p.at("v")); }});
        k.push_back({"linear_shear", "linear shear u = a y (Zermelo's problem)", {{"a", -1.0}}, false,
                     [](const P &p) { return std::make_shared<LinearShear>(p.at("a")); }});
        k.push_back({"double_gyre", "steady double gyre", {{"amplitude", 0.1}, {"length", 1.0}}, false,
                     [](const P &p) { return std::make_shared<DoubleGyre>(p.at("amplitude"), p.at("length")); }});
        k.push_back({"netcdf", "gridded forecast read from a NetCDF file", {}, true, nullptr});
        return k;
    }();
    return kinds;
}

const CurrentFieldKind *findCurrentFieldKind(const std::string &name)
{
    for (const CurrentFieldKind &k : currentFieldKinds())
        if (k.name == name)
            return &k;
    return nullptr;
}

std::string currentFieldKindList(const std::string &separator)
{
    std::string out;
    for (const CurrentFieldKind &k : currentFieldKinds())
        out += (out.empty() ? "" : separator) + k.name;
    return out;
}

std::shared_ptr<const CurrentField> makeAnalyticField(const std::string &name,
                                                      const std::map<std::string, double> &parameters)
{
    const CurrentFieldKind *kind = findCurrentFieldKind(name);
    if (!kind)
        throw Error("unknown current type '" + name + "' (expected one of " + currentFieldKindList() + ")");
    if (kind->gridded)
        throw Error("current type '" + name + "' is read from a file, not made from parameters");
    std::map<std::string, double> full;
    for (const auto &[key, value] : kind->parameters)
        full[key] = value;
    for (const auto &[key, value] : parameters)
    {
        if (!full.count(key))
            throw Error("current type '" + name + "' has no parameter '" + key + "'");
        full[key] = value;
    }
    return kind->make(full);
}
}  // namespace ompl_glider
