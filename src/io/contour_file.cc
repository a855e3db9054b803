// Contour files: see contour_file.h.
#include "hecal/io/contour_file.h"

#include <array>
#include <string_view>

#include "hecal/core/error.h"
#include "hecal/io/point_file.h"

namespace hecal::io {

Eigen::Matrix2Xd ReadContourFile(const std::string& path) {
  constexpr std::array<std::string_view, 2> kColumns = {"x", "y"};
  const PointFile file =
      ReadPointFile(path, kColumns, /*lengths=*/false, LengthUnit::kMetre, "contour points");
  if (file.rows.size() < 4) {
    throw InputError(path, 0,
                     "a closed contour needs at least 4 points, the file has " +
                         std::to_string(file.rows.size()),
                     "give the header x,y and then 4 or more points around the contour");
  }
  Eigen::Matrix2Xd points(2, static_cast<Eigen::Index>(file.rows.size()));
  for (std::size_t i = 0; i < file.rows.size(); ++i) {
    points.col(static_cast<Eigen::Index>(i)) = file.rows[i].value.head<2>();
  }
  return points;
}

}  // namespace hecal::io
