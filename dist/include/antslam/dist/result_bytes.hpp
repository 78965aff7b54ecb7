#pragma once
// The results that farmed runs send between ranks (dist/farm.hpp): every field, so that the
// root writes from received results exactly what it writes from results it computed.

#include "antslam/dist/byte_stream.hpp"
#include "antslam/slamgraph/optimize.hpp"
#include "antslam/tsp/experiment.hpp"

namespace antslam::dist {

void write(dist::ByteWriter& out, const slam::OptimizeResult& r);
slam::OptimizeResult read_optimize_result(dist::ByteReader& in);

void write(dist::ByteWriter& out, const tsp::ExperimentRun& r);
tsp::ExperimentRun read_experiment_run(dist::ByteReader& in);

}  // namespace antslam::dist
