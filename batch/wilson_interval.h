// The Wilson score interval of a success rate: the uncertainty every gate, table and chart of a
// batch reports beside the rate.
#pragma once

#include <cstdint>
#include <utility>

namespace plantsim::batch {

/// Wilson score interval for k successes in n trials (95 %: z = 1.96); (0, 1) when n is 0.
std::pair<double, double> wilson_interval(std::int64_t k, std::int64_t n, double z = 1.96);

}  // namespace plantsim::batch
