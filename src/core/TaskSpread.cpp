// The process's task spreader (TaskSpread.h): set once by an executable, asked by the many-plan modes.
#include "ompl_glider/TaskSpread.h"

#include <atomic>

namespace ompl_glider
{
namespace
{
std::shared_ptr<TaskSpreader> &spreaderSlot()
{
    static std::shared_ptr<TaskSpreader> s;
    return s;
}
std::atomic<int> runsUnderWay{0};
} // namespace

void setTaskSpreader(std::shared_ptr<TaskSpreader> spreader)
{
    spreaderSlot() = std::move(spreader);
}

TaskSpreader *activeTaskSpreader()
{
    TaskSpreader *s = spreaderSlot().get();
    if (!s || s->size() < 2 || runsUnderWay.load() > 0)
        return nullptr;
    return s;
}

int taskRank()
{
    const TaskSpreader *s = spreaderSlot().get();
    return s ? s->rank() : 0;
}

int taskProcesses()
{
    const TaskSpreader *s = spreaderSlot().get();
    return s ? s->size() : 1;
}

TaskSpreadScope::TaskSpreadScope()
{
    ++runsUnderWay;
}

TaskSpreadScope::~TaskSpreadScope()
{
    --runsUnderWay;
}
} // namespace ompl_glider
