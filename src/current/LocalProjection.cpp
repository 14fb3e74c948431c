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
}  // namespace

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
        throw Error("LocalProjection: PROJ could not create '" + impl_->def + "': " +
                    proj_context_errno_string(nullptr, err));
    }
}

LocalProjection::~LocalProjection()
{
    if (impl_->pj)
        proj_destroy(impl_->pj);
    if (impl_->ctx)
        proj_context_destroy(impl_->ctx);
}

void LocalProjection::forward(double lon, double lat, double &x, double &y) const
{
    std::lock_guard<std::mutex> lock(mutex_);
    PJ_COORD c = proj_coord(proj_torad(wrapLon(lon, lon0_)), proj_torad(lat), 0, 0);
    PJ_COORD r = proj_trans(impl_->pj, PJ_FWD, c);
    x = r.xy.x;
    y = r.xy.y;
    if (!std::isfinite(x) || !std::isfinite(y))
        throw Error("LocalProjection: cannot project (" + std::to_string(lon) + ", " + std::to_string(lat) + ")");
}

void LocalProjection::inverse(double x, double y, double &lon, double &lat) const
{
    std::lock_guard<std::mutex> lock(mutex_);
    PJ_COORD c = proj_coord(x, y, 0, 0);
    PJ_COORD r = proj_trans(impl_->pj, PJ_INV, c);
    lon = proj_todeg(r.lp.lam);
    lat = proj_todeg(r.lp.phi);
    if (!std::isfinite(lon) || !std::isfinite(lat))
        throw Error("LocalProjection: cannot invert (" + std::to_string(x) + ", " + std::to_string(y) + ")");
    lon = wrapLon(lon, lon0_);
}

void LocalProjection::eastDirection(double lon, double lat, double &ex, double &ey) const
{
    const double d = 1e-5;  // degrees, about 1 m
    double x1, y1, x2, y2;
    forward(lon - d, lat, x1, y1);
    forward(lon + d, lat, x2, y2);
    const double n = std::hypot(x2 - x1, y2 - y1);
    ex = (x2 - x1) / n;
    ey = (y2 - y1) / n;
}

void LocalProjection::northDirection(double lon, double lat, double &nx, double &ny) const
{
    const double d = 1e-5;
    double x1, y1, x2, y2;
    forward(lon, lat - d, x1, y1);
    forward(lon, lat + d, x2, y2);
    const double n = std::hypot(x2 - x1, y2 - y1);
    nx = (x2 - x1) / n;
    ny = (y2 - y1) / n;
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
}  // namespace ompl_glider
