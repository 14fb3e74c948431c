#pragma once
// Internal to the library: the small text helpers of the CF-attribute, calendar and NetCDF parsers. Not installed.
#include <cctype>
#include <initializer_list>
#include <string>
#include <vector>

namespace ompl_glider::text
{
/// The text on one line, as line-based files hold it (a goto list's comment, a targets file's header): every control
/// character (a line break, a tab, NUL, DEL) becomes a space, so a name cannot end its line and start another.
inline std::string oneLine(std::string s)
{
    for (char &c : s)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
            c = ' ';
    return s;
}

/// ASCII lower case.
inline std::string lower(std::string s)
{
    for (char &c : s)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

/// Without leading and trailing white space and NUL characters (NetCDF text attributes are often NUL-padded).
inline std::string trim(const std::string &s)
{
    auto blank = [](char c) { return std::isspace(static_cast<unsigned char>(c)) || c == '\0'; };
    std::size_t a = 0, b = s.size();
    while (a < b && blank(s[a]))
        ++a;
    while (b > a && blank(s[b - 1]))
        --b;
    return s.substr(a, b - a);
}

/// True when s equals one of the names.
inline bool inList(const std::string &s, std::initializer_list<const char *> names)
{
    for (const char *x : names)
        if (s == x)
            return true;
    return false;
}

/// "a, b, c".
inline std::string joinNames(const std::vector<std::string> &names)
{
    std::string s;
    for (std::size_t i = 0; i < names.size(); ++i)
        s += (i ? ", " : "") + names[i];
    return s;
}
}  // namespace ompl_glider::text
