#pragma once
// The journal of a strength search, <output>/strength/journal.txt: every finished trial
// (its index, load and what was judged of it, numbers to 17 digits), rewritten whole,
// synced and renamed into place (engine/atomic_file.hpp) as each trial ends, and closed by
// a CRC-32 of the lines above it. `pdq strength --resume` reads it back, and the search
// takes those trials from it instead of running them again (strength::Options::done).
#include <cstdint>
#include <string>
#include <vector>

#include "engine/params.hpp"
#include "studies/strength.hpp"

namespace pdq::strength {

std::string journalPath(const std::string& strengthDir);

// Names a search: its scenario's hash (io/checkpoint.hpp) and its options.
std::uint64_t searchHash(std::uint64_t scenario, const Params& options);

void writeJournal(const std::string& path, std::uint64_t search, const std::vector<Trial>& trials);

// The trials of the journal at `path`. InputError when it is missing, cut short or damaged,
// or (unless `force`) of another search.
std::vector<Trial> readJournal(const std::string& path, std::uint64_t search, bool force);

}  // namespace pdq::strength
