#include "ompl_glider/current/LocalProjection.h"

#include <proj.h>

#include <cmath>
#include <sstream>

#include "ompl_glider/Exception.h"

namespace ompl_glider
{
struct LocalProjection::Impl
{
    PJ_CONTEXT *ctx{nullptr};
    PJ *pj{nullptr};
    std::string def;
};

namespace
{
double wrapLon(double lon, double lon0)
{
    double d = std::fmod(lon - lon0 + 180.0, 360.0);
    if (d < 0)
        d += 360.0;
    return lon0 + d - 180.0;
}
} // namespace

LocalProjection::LocalProjection(double lon0, double lat0) : lon0_(lon0), lat0_(lat0), impl_(new Impl)
{
    if (!std::isfinite(lon0) || !std::isfinite(lat0) || std::abs(lat0) > 90.0)
        throw Error("LocalProjection: reference point (" + std::to_string(lon0) + ", " + std::to_string(lat0) +
                    ") is not a valid longitude/latitude");
    lon0_ = wrapLon(lon0, 0.0);
    std::ostringstream os;
    os.precision(17);
    os << "+proj=aeqd +lat_0=" << lat0_ << " +lon_0=" << lon0_ << " +x_0=0 +y_0=0 +ellps=WGS84 +units=m +no_defs";
    impl_->def = os.str();
    impl_->ctx = proj_context_create();
    impl_->pj = proj_create(impl_->ctx, impl_->def.c_str());
    if (!impl_->pj)
    {
        const int err = proj_context_errno(impl_->ctx);
        proj_context_destroy(impl_->ctx);
        throw Error("LocalProjection: PROJ could not create '" + impl_->def +
                    "': " + proj_context_errno_string(nullptr, err));
    }
}

LocalProjection::~LocalProjection()
{
    if (impl_->pj)
        proj_destroy(impl_->pj);
    if (impl_->ctx)
        proj_context_destroy(impl_->ctx);
}

Point2 LocalProjection::forward(double lon, double lat) const
{
    std::lock_guard<std::mutex> lock(mutex_);
    // normalised first (exactly), so that 185 and -175 give the same point to the last bit
    PJ_COORD c = proj_coord(proj_torad(wrapLon(normalizeLongitude(lon), lon0_)), proj_torad(lat), 0, 0);
    PJ_COORD r = proj_trans(impl_->pj, PJ_FWD, c);
    const Point2 p{r.xy.x, r.xy.y};
    if (!std::isfinite(p.x) || !std::isfinite(p.y))
        throw Error("LocalProjection: cannot project (" + std::to_string(lon) + ", " + std::to_string(lat) + ")");
    return p;
}

LonLat LocalProjection::inverse(double x, double y) const
{
    std::lock_guard<std::mutex> lock(mutex_);
    PJ_COORD c = proj_coord(x, y, 0, 0);
    PJ_COORD r = proj_trans(impl_->pj, PJ_INV, c);
    LonLat g{proj_todeg(r.lp.lam), proj_todeg(r.lp.phi)};
    if (!std::isfinite(g.lon) || !std::isfinite(g.lat))
        throw Error("LocalProjection: cannot invert (" + std::to_string(x) + ", " + std::to_string(y) + ")");
    g.lon = normalizeLongitude(g.lon); // the one place planning-frame points become longitudes: -180..180
    return g;
}

void LocalProjection::eastDirection(double lon, double lat, double &ex, double &ey) const
{
    const double d = 1e-5; // degrees, about 1 m
    const Point2 a = forward(lon - d, lat), b = forward(lon + d, lat);
    const double n = std::hypot(b.x - a.x, b.y - a.y);
    ex = (b.x - a.x) / n;
    ey = (b.y - a.y) / n;
}

void LocalProjection::northDirection(double lon, double lat, double &nx, double &ny) const
{
    const double d = 1e-5;
    const Point2 a = forward(lon, lat - d), b = forward(lon, lat + d);
    const double n = std::hypot(b.x - a.x, b.y - a.y);
    nx = (b.x - a.x) / n;
    ny = (b.y - a.y) / n;
}

double LocalProjection::geodesicDistance(double lon1, double lat1, double lon2, double lat2) const
{
    std::lock_guard<std::mutex> lock(mutex_);
    PJ_COORD a = proj_coord(proj_torad(lon1), proj_torad(lat1), 0, 0);
    PJ_COORD b = proj_coord(proj_torad(lon2), proj_torad(lat2), 0, 0);
    return proj_lp_dist(impl_->pj, a, b);
}

std::string LocalProjection::definition() const
{
    return impl_->def;
}
} // namespace ompl_glider
