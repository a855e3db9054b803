// Uses the installed headers and libraries: a rotation round trip and a pose-table round trip.
#include <cmath>
#include <cstdio>

#include "hecal/geometry/so3.h"
#include "hecal/io/pose_table.h"

int main() {
  const Eigen::Vector3d omega(0.1, -0.2, 0.3);
  const double so3_error = (hecal::so3::Log(hecal::so3::Exp(omega)) - omega).norm();

  hecal::io::PoseTable table;
  table.rows.push_back({hecal::MakePose(hecal::so3::Exp(omega), Eigen::Vector3d(1, 2, 3))});
  const std::string text = hecal::io::FormatPoseTable(table, hecal::io::PoseWriteOptions{});
  const hecal::io::PoseTable back = hecal::io::ParsePoseTable(text, "memory", {});
  const double io_error = (back.rows.at(0).pose.matrix() - table.rows[0].pose.matrix()).norm();

  std::printf("so3 %.3g io %.3g\n", so3_error, io_error);
  return so3_error < 1e-12 && io_error < 1e-12 ? 0 : 1;
}
