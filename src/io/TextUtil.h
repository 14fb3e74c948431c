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

/// The text as valid UTF-8: each byte that does not start or continue a well-formed sequence (a Latin-1 name, a
/// truncated character; overlong forms and surrogates included) becomes U+FFFD, as a text or XML file needs.
inline std::string validUtf8(const std::string &s)
{
    std::string out;
    out.reserve(s.size());
    const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(s[i]); };
    for (std::size_t i = 0; i < s.size();)
    {
        const unsigned char c = byte(i);
        std::size_t n = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xe ? 3 : (c >> 3) == 0x1e ? 4 : 0;
        bool ok = n > 0 && i + n <= s.size() && !(c == 0xc0 || c == 0xc1 || c > 0xf4);
        for (std::size_t k = 1; ok && k < n; ++k)
            ok = (byte(i + k) & 0xc0) == 0x80;
        if (ok && n == 3) // no overlong form, no surrogate
            ok = !(c == 0xe0 && byte(i + 1) < 0xa0) && !(c == 0xed && byte(i + 1) >= 0xa0);
        if (ok && n == 4) // no overlong form, nothing past U+10FFFF
            ok = !(c == 0xf0 && byte(i + 1) < 0x90) && !(c == 0xf4 && byte(i + 1) >= 0x90);
        if (ok)
        {
            out.append(s, i, n);
            i += n;
        }
        else
        {
            out += "\xEF\xBF\xBD";
            ++i;
        }
    }
    return out;
}

/// Text for XML character data and attributes (KML, SVG): valid UTF-8 (the files declare it), the control
/// characters XML 1.0 does not allow as spaces, the markup characters escaped.
inline std::string xmlEscaped(const std::string &t)
{
    std::string out;
    for (char c : validUtf8(t))
        switch (c)
        {
        case '&':
            out += "&amp;";
            break;
        case '<':
            out += "&lt;";
            break;
        case '>':
            out += "&gt;";
            break;
        case '"':
            out += "&quot;";
            break;
        case '\t':
        case '\n':
        case '\r':
            out += c;
            break;
        default:
            out += static_cast<unsigned char>(c) < 0x20 ? ' ' : c;
        }
    return out;
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
} // namespace ompl_glider::text
