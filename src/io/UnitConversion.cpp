// Unit strings read with UDUNITS-2: the database loaded once, every call serialised (UDUNITS-2's parser keeps
// global state), its error messages silenced while it runs.
#include "ompl_glider/io/UnitConversion.h"

#include <udunits2.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "TextUtil.h"
#include "ompl_glider/Exception.h"

namespace ompl_glider
{
namespace
{
/// Silences UDUNITS-2's messages (it prints to stderr by default) while in scope, restoring the handler before.
class QuietUdunits
{
public:
    QuietUdunits() : previous_(ut_set_error_message_handler(ut_ignore)) {}
    ~QuietUdunits() { ut_set_error_message_handler(previous_); }
    QuietUdunits(const QuietUdunits &) = delete;
    QuietUdunits &operator=(const QuietUdunits &) = delete;

private:
    ut_error_message_handler previous_;
};

/// Every call into UDUNITS-2 holds this lock.
std::mutex &udunitsMutex()
{
    static std::mutex m;
    return m;
}

/// The unit database, read at the first use and freed at exit.
class UnitDatabase
{
public:
    UnitDatabase()
    {
        QuietUdunits quiet;
        system_ = ut_read_xml(nullptr);
        if (!system_)
        {
            ut_status status = UT_SUCCESS;
            const char *path = ut_get_path_xml(nullptr, &status);
            error_ = std::string("cannot read the UDUNITS-2 unit database '") + (path ? path : "?") +
                     "' (install libudunits2-data, or name the database with the environment variable "
                     "UDUNITS2_XML_PATH)";
        }
    }
    ~UnitDatabase()
    {
        if (system_)
            ut_free_system(system_);
    }
    UnitDatabase(const UnitDatabase &) = delete;
    UnitDatabase &operator=(const UnitDatabase &) = delete;

    /// @throws Error when the database could not be read.
    ut_system *system() const
    {
        if (!system_)
            throw Error(error_);
        return system_;
    }

private:
    ut_system *system_{nullptr};
    std::string error_;
};

/// Call with udunitsMutex() held.
ut_system *unitSystem()
{
    static UnitDatabase db; // initialised once, thread-safely (and under the lock anyway)
    return db.system();
}

using UnitPtr = std::unique_ptr<ut_unit, decltype(&ut_free)>;

UnitPtr parse(ut_system *sys, const std::string &text)
{
    return UnitPtr(ut_parse(sys, text.c_str(), UT_ASCII), &ut_free);
}

/// How UDUNITS-2 writes a unit in base units ("K @ 273.15" for degC, "m.s-1" for m/s).
std::string canonical(const ut_unit *unit)
{
    char buf[256];
    const int n = ut_format(unit, buf, sizeof buf, UT_ASCII | UT_DEFINITION);
    return n >= 0 && std::size_t(n) < sizeof buf ? std::string(buf, std::size_t(n)) : std::string("?");
}

/// Spellings written in forecast files that UDUNITS-2 does not read as velocities, keyed by their lower-case form
/// without blanks (the unit lists of earlier versions of this reader accepted them): "mps" and the run-together
/// "meterspersecond" it cannot parse, "kn" it does not know, and "ms-1" / "cms-1" (m s-1 written without the
/// blank) it reads as per millisecond / centimetre-millisecond, which no velocity variable means.
std::optional<std::string> velocityAlias(const std::string &units)
{
    std::string key;
    for (char c : text::lower(units))
        if (!std::isspace(static_cast<unsigned char>(c)))
            key += c;
    static const std::vector<std::pair<std::vector<std::string>, std::string>> aliases = {
        {{"mps", "meterspersecond", "metrespersecond", "ms-1", "ms^-1", "ms**-1"}, "m/s"},
        {{"cms-1", "cms^-1", "cms**-1", "centimeterspersecond", "centimetrespersecond"}, "cm/s"},
        {{"kn"}, "knot"}};
    for (const auto &[names, to] : aliases)
        for (const std::string &n : names)
            if (key == n)
                return to;
    return std::nullopt;
}

/// The conversion of `units` to the unit `target` (a quantity named `what` in messages, with `examples`).
LinearConversion convertTo(const std::string &units, const char *target, const std::string &what,
                           const std::string &examples, bool aliases)
{
    std::string text = text::trim(units);
    if (aliases)
        if (auto a = velocityAlias(text))
            text = *a;
    std::vector<std::string> tries{text};
    if (text::lower(text) != text)
        tries.push_back(text::lower(text)); // "M/S", "CM/S", "KT": UDUNITS-2 is case-sensitive

    std::lock_guard<std::mutex> lock(udunitsMutex());
    QuietUdunits quiet;
    ut_system *sys = unitSystem();
    const UnitPtr to = parse(sys, target);
    if (!to)
        throw Error(std::string("UDUNITS-2 does not know the unit '") + target + "'");
    std::string readAs; // how the first spelling UDUNITS-2 could parse reads
    for (const std::string &t : tries)
    {
        const UnitPtr unit = parse(sys, t);
        if (!unit)
            continue;
        if (readAs.empty())
            readAs = canonical(unit.get());
        if (!ut_are_convertible(unit.get(), to.get()))
            continue;
        std::unique_ptr<cv_converter, decltype(&cv_free)> conv(ut_get_converter(unit.get(), to.get()), &cv_free);
        if (!conv)
            continue;
        LinearConversion c;
        c.offset = cv_convert_double(conv.get(), 0.0);
        c.factor = cv_convert_double(conv.get(), 1.0) - c.offset;
        const double probe = cv_convert_double(conv.get(), 1000.0);
        if (!std::isfinite(c.factor) || !std::isfinite(c.offset) || c.factor == 0.0 ||
            !(std::abs(probe - c(1000.0)) <= 1e-9 * std::max(1.0, std::abs(probe))))
            throw Error("units '" + units + "' do not convert linearly to " + target + " (UDUNITS-2 reads them as '" +
                        readAs + "')");
        return c;
    }
    if (readAs.empty())
        throw Error("units '" + units + "' not understood (UDUNITS-2 cannot parse them); expected " + what +
                    " such as " + examples);
    throw Error("units '" + units + "' are not " + what + " (UDUNITS-2 reads them as '" + readAs +
                "', which does not convert to " + target + ")");
}
} // namespace

LinearConversion velocityToMetresPerSecond(const std::string &units)
{
    return convertTo(units, "m/s", "a velocity", "m/s, m s-1, cm/s, knots or km/h", true);
}

LinearConversion lengthToMetres(const std::string &units)
{
    return convertTo(units, "m", "a length", "m or km", false);
}

bool isDimensionless(const std::string &units)
{
    std::lock_guard<std::mutex> lock(udunitsMutex());
    QuietUdunits quiet;
    ut_system *sys = unitSystem();
    const UnitPtr unit = parse(sys, text::trim(units));
    return unit && ut_are_convertible(unit.get(), ut_get_dimensionless_unit_one(sys));
}
} // namespace ompl_glider
