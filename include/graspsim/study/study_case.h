#pragma once
/// @file
/// The cases of a study (one simulation each) and their split into shards.
///
/// Cases are numbered from 0 in a fixed order: on a grid the last axis varies fastest; when
/// sampling, draw by draw from the study's seed. The numbering depends only on the study file,
/// so every process (a local run, each task of a Slurm job array) agrees on it.

#include "graspsim/study/study_spec.h"

#include <string>
#include <vector>

namespace graspsim::study {

/// One run of the study: the value (YAML text) of each axis, in the study's axis order.
struct StudyCase {
    int index = 0;                    ///< 0-based number, stable for a given study file
    std::vector<std::string> values;  ///< one per StudySpec::axes
};

/// Every case of the study: the full grid, or `samples` random or Latin-hypercube draws.
/// Numbers drawn from a range are written with 6 significant digits, grid values with 12, so
/// the same text reaches the scenario file and the results table.
std::vector<StudyCase> expandCases(const StudySpec& spec);

/// Task `index` of `count` (0 <= index < count): the shard holding every case whose number is
/// index modulo count, so that the shards of any count run every case exactly once.
struct Shard {
    int index = 0;
    int count = 1;

    bool holds(int caseIndex) const { return caseIndex % count == index; }
};

/// Parses "i/K" (0 <= i < K), e.g. "3/8" or Slurm's "$SLURM_ARRAY_TASK_ID/$SLURM_ARRAY_TASK_COUNT".
/// @throws graspsim::InputError naming --shard and what is accepted.
Shard parseShard(const std::string& text);

/// The cases of `cases` that `shard` holds, in order.
std::vector<StudyCase> selectShard(const std::vector<StudyCase>& cases, const Shard& shard);

}  // namespace graspsim::study
