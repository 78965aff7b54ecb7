#pragma once
// The results that farmed runs send between ranks (cli/farm.hpp): every field, so that the
// root writes from received results exactly what it writes from results it computed.

#include "dist/byte_stream.hpp"
#include "slamgraph/optimize.hpp"
#include "tsp/experiment.hpp"

namespace antslam::cli {

void write(dist::ByteWriter& out, const slam::OptimizeResult& r);
slam::OptimizeResult read_optimize_result(dist::ByteReader& in);

void write(dist::ByteWriter& out, const tsp::ExperimentRun& r);
tsp::ExperimentRun read_experiment_run(dist::ByteReader& in);

}  // namespace antslam::cli
