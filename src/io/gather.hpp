#pragma once
// Gathers rows of doubles from the owned particles of every rank onto rank 0, sorted by
// the first column(s): output files list particles in global-ID order whatever the number
// of ranks.
#include <vector>

#include "engine/comm.hpp"

namespace pdq {

std::vector<double> gatherSortedRows(const Comm& comm, const std::vector<double>& rows, int width,
                                     int keyColumns = 1);

}  // namespace pdq
