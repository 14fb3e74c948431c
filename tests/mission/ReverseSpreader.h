#pragma once
// A TaskSpreader of "two processes" for tests of the many-plan modes without MPI: it runs the tasks in this process,
// last first, through their bytes (as a job's ranks hand results back), and counts the runs.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "ompl_glider/TaskSpread.h"

namespace ompl_glider::test
{
class ReverseSpreader : public TaskSpreader
{
public:
    int rank() const override { return 0; }
    int size() const override { return 2; }
    std::vector<std::string> run(const std::string &what, std::size_t n, const Task &task,
                                 const Progress &progress) override
    {
        const TaskSpreadScope scope;
        EXPECT_EQ(activeTaskSpreader(), nullptr) << "a task's own tasks run locally";
        runs.push_back(what + " x" + std::to_string(n));
        std::vector<std::string> out(n);
        for (std::size_t i = n; i-- > 0;)
        {
            out[i] = task(i);
            if (progress)
                progress(n - i, n);
        }
        return out;
    }
    std::vector<std::string> runs; ///< "what xN" per run()
};
} // namespace ompl_glider::test
