// OpenCV's hand–eye functions as the benchmark's peer: see opencv_bench_peer.h.
#include "hecal/jobs/opencv_bench_peer.h"

#include <memory>
#include <optional>
#include <vector>

#include "hecal/peers/opencv_handeye.h"

namespace hecal::jobs {

bool HasOpenCvBenchPeer(estimation::Method method) {
  const std::optional<handeye::ClosedForm> form = estimation::Info(method).closed_form;
  return form && peers::HasOpenCvPeer(*form);
}

study::BenchPeer OpenCvBenchPeer() {
  study::BenchPeer peer;
  peer.name = "opencv";
  peer.prepare =
      [](estimation::Method method,
         const std::vector<study::BenchDataSet>& sets) -> std::optional<study::BenchSolver> {
    if (!HasOpenCvBenchPeer(method)) return std::nullopt;
    auto inputs = std::make_shared<std::vector<peers::OpenCvInput>>();
    for (const study::BenchDataSet& set : sets) {
      inputs->push_back(peers::PrepareOpenCvInput(set.problem));
    }
    return [form = *estimation::Info(method).closed_form, inputs](std::size_t i) {
      return peers::SolveWithOpenCv(form, (*inputs)[i], /*estimate_z=*/false).X;
    };
  };
  return peer;
}

}  // namespace hecal::jobs
