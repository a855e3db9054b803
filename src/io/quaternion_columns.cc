// Quaternion columns of a pose table: see quaternion_columns.h.
#include "hecal/io/quaternion_columns.h"

namespace hecal::io {

bool HasQuaternionColumns(const PoseTable& table) {
  return table.rotation && table.rotation->kind == RotationFormat::Kind::kQuaternion;
}

}  // namespace hecal::io
