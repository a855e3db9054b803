// `hecal simulate --streams`: see simulate_streams.h.
#include "simulate_streams.h"

#include <filesystem>

#include "bounds.h"

namespace hecal::cli {
namespace {

// The first trial's recording as pose files with stamps, and its truth.
std::vector<io::OutputFile> RecordingFiles(const jobs::StreamStudyOptions& options,
                                           const std::string& dir) {
  const sim::SimulatedStreams data =
      jobs::SimulateStreamTrial(options, options.setups.front(), options.sigmas.front(), 0);
  const auto table = [](const std::vector<double>& stamps, const std::vector<Pose>& poses) {
    io::PoseTable out;
    for (size_t k = 0; k < stamps.size(); ++k) {
      io::PoseRow row;
      row.pose = poses[k];
      row.stamp = stamps[k];
      out.rows.push_back(row);
    }
    return out;
  };
  io::PoseWriteOptions write;
  const std::filesystem::path folder(dir);
  char truth[600];
  const Eigen::Quaterniond qx(data.X.linear()), qz(data.Z.linear());
  std::snprintf(truth, sizeof truth,
                "{\"setup\": \"%s\", \"time_offset\": %.9f,\n"
                " \"time_offset_convention\": \"a camera sample stamped t was taken at "
                "robot-clock time t + time_offset\",\n"
                " \"X\": {\"translation\": [%.9f, %.9f, %.9f], \"quaternion_wxyz\": [%.9f, %.9f, "
                "%.9f, %.9f]},\n"
                " \"Z\": {\"translation\": [%.9f, %.9f, %.9f], \"quaternion_wxyz\": [%.9f, %.9f, "
                "%.9f, %.9f]}, \"units\": {\"length\": \"m\"}}\n",
                std::string(handeye::SetupName(data.setup)).c_str(), data.time_offset,
                data.X.translation().x(), data.X.translation().y(), data.X.translation().z(),
                qx.w(), qx.x(), qx.y(), qx.z(), data.Z.translation().x(), data.Z.translation().y(),
                data.Z.translation().z(), qz.w(), qz.x(), qz.y(), qz.z());
  return {{"--write-streams", (folder / "robot.csv").string(),
           io::FormatPoseTable(table(data.robot_stamps, data.T_base_gripper), write)},
          {"--write-streams", (folder / "camera.csv").string(),
           io::FormatPoseTable(table(data.camera_stamps, data.T_camera_target), write)},
          {"--write-streams", (folder / "truth.json").string(), truth}};
}

}  // namespace

void AddStreamStudyFlags(CLI::App& simulate, StreamStudyFlags& flags) {
  jobs::StreamStudyOptions& o = flags.options;
  simulate.add_flag("--streams", flags.streams,
                    "The stream study: recordings with a clock offset, calibrated with "
                    "calibrate --streams (docs/streams.md)");
  simulate
      .add_option("--offset-range", o.offset_range,
                  "With --streams: clock offsets drawn from +-this many seconds")
      ->capture_default_str();
  simulate.add_option("--robot-rate", o.simulation.robot_rate, "With --streams: robot stream, Hz")
      ->capture_default_str();
  simulate
      .add_option("--camera-rate", o.simulation.camera_rate, "With --streams: camera stream, Hz")
      ->capture_default_str();
  simulate.add_option("--duration", o.simulation.duration, "With --streams: seconds of recording")
      ->capture_default_str();
  simulate.add_option("--write-streams", flags.write_streams,
                      "With --streams: write the first trial's robot.csv, camera.csv and "
                      "truth.json to this folder");
}

void RunSimulateStreams(const jobs::SimulateOptions& simulate, StreamStudyFlags flags,
                        const std::string& output, const std::string& summary, const Io& io) {
  jobs::StreamStudyOptions& o = flags.options;
  o.setups = simulate.setups;
  if (flags.sigma_given) o.sigmas = simulate.sigmas;
  o.noise = simulate.noise.front();
  o.trials = simulate.trials;
  o.seed = simulate.seed;
  o.threads = simulate.threads;
  o.estimate_noise = simulate.estimate_noise;
  RequireValid(o);
  std::vector<io::OutputFile> outputs;
  if (!flags.write_streams.empty()) outputs = RecordingFiles(o, flags.write_streams);
  std::vector<io::PathArgument> checked = {{"--output", output}, {"--summary", summary}};
  for (const io::OutputFile& file : outputs) checked.push_back({file.flag, file.path});
  io::CheckOutputs(checked, {});
  const jobs::StreamStudyResult result = jobs::RunStreamStudy(o);
  const std::string text = jobs::StreamStudyText(result);
  if (!output.empty()) outputs.push_back({"--output", output, jobs::StreamTrialsCsv(result)});
  if (!summary.empty()) outputs.push_back({"--summary", summary, text});
  io::WriteFilesAtomically(outputs);
  io.out << text;
  for (const io::OutputFile& file : outputs) io.out << "hecal: wrote " << file.path << "\n";
}

}  // namespace hecal::cli
