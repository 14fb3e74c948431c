// The stop request of the plans under way (see StopRequest.h).
#include "ompl_glider/StopRequest.h"

#include <atomic>

namespace ompl_glider
{
namespace
{
std::atomic<bool> g_stop{false};
} // namespace

void requestStop()
{
    g_stop.store(true);
}

void clearStop()
{
    g_stop.store(false);
}

bool stopRequested()
{
    return g_stop.load(std::memory_order_relaxed);
}
} // namespace ompl_glider
