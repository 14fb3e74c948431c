// The size a classic-format file (CDF-1, CDF-2 or CDF-5) must have, from its header. NetCDF-C reads a cut file
// as if it were complete (the missing bytes read as zeros or fill values, and a header cut early may even open),
// and it does not expose the variables' offsets, so the reader parses just enough of the header of the public
// classic format (magic, numrecs, dim_list, gatt_list, var_list with each variable's begin) to know where the
// data end.
#include <algorithm>
#include <fstream>
#include <limits>

#include <netcdf.h>

#include "GriddedDataset.h"

namespace ompl_glider
{
namespace gridded_detail
{
namespace
{
constexpr std::uint64_t kMax = std::numeric_limits<std::uint64_t>::max();
constexpr std::uint64_t kDimensionTag = 0x0A, kVariableTag = 0x0B, kAttributeTag = 0x0C;

/// Thrown when the bytes end inside the header.
struct CutShort
{
};
/// Thrown when the bytes are not a classic header (an unknown tag, type or dimension id).
struct NotClassic
{
    std::string why;
};

/// a * b, saturating at kMax.
std::uint64_t mulSat(std::uint64_t a, std::uint64_t b)
{
    return a != 0 && b > kMax / a ? kMax : a * b;
}

/// a + b, saturating at kMax.
std::uint64_t addSat(std::uint64_t a, std::uint64_t b)
{
    return b > kMax - a ? kMax : a + b;
}

/// n rounded up to a multiple of 4 (the header's and the data's alignment).
std::uint64_t pad4(std::uint64_t n)
{
    return n > kMax - 3 ? kMax : (n + 3) / 4 * 4;
}

/// Bytes of one value of a classic type (NC_BYTE .. NC_UINT64). @throws NotClassic for another type.
std::uint64_t typeBytes(std::uint64_t type)
{
    switch (type)
    {
    case NC_BYTE:
    case NC_CHAR:
    case NC_UBYTE:
        return 1;
    case NC_SHORT:
    case NC_USHORT:
        return 2;
    case NC_INT:
    case NC_FLOAT:
    case NC_UINT:
        return 4;
    case NC_DOUBLE:
    case NC_INT64:
    case NC_UINT64:
        return 8;
    default:
        throw NotClassic{"unknown type " + std::to_string(type)};
    }
}

/// Big-endian reads from the first `size` bytes of a stream; CutShort when they end.
class HeaderReader
{
public:
    HeaderReader(std::istream &in, std::uint64_t size) : in_(in), size_(size) {}
    std::uint64_t pos() const { return pos_; }
    /// An unsigned big-endian integer of `bytes` (4 or 8) bytes.
    std::uint64_t uint(int bytes)
    {
        need(std::uint64_t(bytes));
        unsigned char b[8];
        if (!in_.read(reinterpret_cast<char *>(b), bytes))
            throw CutShort{};
        pos_ += std::uint64_t(bytes);
        std::uint64_t v = 0;
        for (int k = 0; k < bytes; ++k)
            v = (v << 8) | b[k];
        return v;
    }
    void skip(std::uint64_t bytes)
    {
        need(bytes);
        if (!in_.seekg(static_cast<std::streamoff>(bytes), std::ios::cur))
            throw CutShort{};
        pos_ += bytes;
    }
    /// Skips `count` values of `each` bytes, padded to 4.
    void skipValues(std::uint64_t count, std::uint64_t each)
    {
        if (count > (size_ - pos_) / each)
            throw CutShort{};
        skip(pad4(count * each));
    }

private:
    void need(std::uint64_t n) const
    {
        if (n > size_ - pos_)
            throw CutShort{};
    }
    std::istream &in_;
    std::uint64_t size_;
    std::uint64_t pos_{0};
};

/// The header's sizes: NON_NEG (4 bytes, 8 in CDF-5) and OFFSET (4 bytes in CDF-1, else 8).
struct Widths
{
    int nonNeg{4}, offset{4};
};

/// The element count of a list with the given tag (0 for ABSENT). @throws NotClassic for another tag.
std::uint64_t listLength(HeaderReader &r, const Widths &w, std::uint64_t tag)
{
    const std::uint64_t t = r.uint(4), n = r.uint(w.nonNeg);
    if (t == 0 && n == 0)
        return 0;
    if (t != tag)
        throw NotClassic{"list tag " + std::to_string(t) + " where " + std::to_string(tag) + " belongs"};
    return n;
}

/// Skips an attribute list (global or a variable's).
void skipAttributes(HeaderReader &r, const Widths &w)
{
    const std::uint64_t n = listLength(r, w, kAttributeTag);
    for (std::uint64_t k = 0; k < n; ++k)
    {
        r.skipValues(r.uint(w.nonNeg), 1); // name
        const std::uint64_t each = typeBytes(r.uint(4));
        r.skipValues(r.uint(w.nonNeg), each);
    }
}

/// One variable of the header: where its values begin, their bytes (per record for record variables).
struct VarExtent
{
    std::uint64_t begin{0}, bytes{0};
    bool record{false};
};

/// Reads one variable (name, dimension ids, attributes, type, vsize, begin); its bytes from the dimensions (vsize
/// saturates at 2^32 - 1 for large variables).
VarExtent readVariable(HeaderReader &r, const Widths &w, const std::vector<std::uint64_t> &dimLen)
{
    r.skipValues(r.uint(w.nonNeg), 1); // name
    const std::uint64_t ndims = r.uint(w.nonNeg);
    VarExtent v;
    std::uint64_t values = 1;
    for (std::uint64_t k = 0; k < ndims; ++k)
    {
        const std::uint64_t id = r.uint(w.nonNeg);
        if (id >= dimLen.size())
            throw NotClassic{"dimension id " + std::to_string(id) + " of " + std::to_string(dimLen.size())};
        if (k == 0 && dimLen[id] == 0)
            v.record = true;
        else
            values = mulSat(values, dimLen[id]);
    }
    skipAttributes(r, w);
    v.bytes = mulSat(values, typeBytes(r.uint(4)));
    if (v.bytes == kMax)
        throw NotClassic{"a variable of more than 2^64 bytes"};
    r.uint(w.nonNeg); // vsize
    v.begin = r.uint(w.offset);
    return v;
}

/// Where the values end: the last non-record variable, and the last record (records are the record variables'
/// slabs padded to 4 bytes, without padding when there is only one record variable).
void setDataEnds(const std::vector<VarExtent> &vars, std::uint64_t numRecs, ClassicExtent &e)
{
    std::uint64_t recSize = 0, nRec = 0;
    e.dataBegin = vars.empty() ? e.headerEnd : kMax;
    for (const VarExtent &v : vars)
    {
        e.dataBegin = std::min(e.dataBegin, v.begin);
        if (!v.record)
            e.fixedEnd = std::max(e.fixedEnd, addSat(v.begin, v.bytes));
        else
        {
            recSize = addSat(recSize, pad4(v.bytes));
            ++nRec;
        }
    }
    if (nRec == 1)
        for (const VarExtent &v : vars)
            if (v.record)
                recSize = v.bytes;
    if (e.streaming || numRecs == 0)
        return;
    for (const VarExtent &v : vars)
        if (v.record)
            e.recordEnd = std::max(e.recordEnd, addSat(addSat(v.begin, mulSat(numRecs - 1, recSize)), v.bytes));
}
} // namespace

std::uint64_t ClassicExtent::dataEnd() const
{
    return std::max(headerEnd, std::max(fixedEnd, recordEnd));
}

ClassicExtent classicExtent(std::istream &in, std::uint64_t size)
{
    ClassicExtent e;
    e.fileBytes = size;
    HeaderReader r(in, size);
    try
    {
        const std::uint64_t magic = r.uint(4);
        const std::uint64_t version = magic & 0xFF;
        if ((magic >> 8) != 0x434446 || (version != 1 && version != 2 && version != 5)) // "CDF"
            return e;
        e.version = int(version);
        const Widths w{e.version == 5 ? 8 : 4, e.version == 1 ? 4 : 8};
        const std::uint64_t numRecs = r.uint(w.nonNeg);
        e.streaming = numRecs == (e.version == 5 ? kMax : 0xFFFFFFFFull);
        std::vector<std::uint64_t> dimLen;
        for (std::uint64_t k = 0, n = listLength(r, w, kDimensionTag); k < n; ++k)
        {
            r.skipValues(r.uint(w.nonNeg), 1); // name
            dimLen.push_back(r.uint(w.nonNeg));
        }
        skipAttributes(r, w);
        std::vector<VarExtent> vars;
        for (std::uint64_t k = 0, n = listLength(r, w, kVariableTag); k < n; ++k)
            vars.push_back(readVariable(r, w, dimLen));
        e.headerEnd = r.pos();
        setDataEnds(vars, numRecs, e);
    }
    catch (const CutShort &)
    {
        e.headerCut = true;
    }
    catch (const NotClassic &bad)
    {
        // after a classic magic number, a header that breaks the format is corrupt (NetCDF-C may divide by zero
        // or allocate what it declares); without one, the file is simply not classic
        if (e.version != 0)
            e.corrupt = bad.why;
    }
    return e;
}

std::optional<std::string> classicTruncation(const std::string &path)
{
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in)
        return std::nullopt;
    const std::streamoff size = in.tellg();
    if (size < 0 || !in.seekg(0))
        return std::nullopt;
    const ClassicExtent e = classicExtent(in, std::uint64_t(size));
    const std::string s = std::to_string(e.fileBytes);
    if (e.version == 0)
        return std::nullopt;
    if (!e.corrupt.empty())
        return "is corrupt: its classic-format header is broken (" + e.corrupt + ")";
    if (e.headerCut)
        return "is truncated or corrupt: it ends inside its header, after " + s +
               " bytes (or its header declares more values than the file holds)";
    const std::uint64_t end = e.dataEnd();
    if (end <= e.fileBytes)
        return std::nullopt;
    return "is truncated: its header declares " + std::to_string(end - std::min(end, e.dataBegin)) +
           " bytes of data ending at byte " + std::to_string(end) + ", the file has " + s + " bytes (" +
           std::to_string(end - e.fileBytes) + " missing)";
}
} // namespace gridded_detail
} // namespace ompl_glider
