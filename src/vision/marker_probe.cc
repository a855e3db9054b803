// The square markers an image shows: see marker_probe.h.
#include "hecal/vision/marker_probe.h"

#include <algorithm>
#include <opencv2/aruco.hpp>
#include <set>
#include <span>
#include <string_view>
#include <vector>

#include "hecal/pose/target.h"

namespace hecal::vision {
namespace {

// The largest dictionary of each kind, and its AprilTag family name (empty for ArUco).
struct Kind {
  cv::aruco::PREDEFINED_DICTIONARY_NAME dictionary;
  std::string_view family;
};
constexpr Kind kKinds[] = {{cv::aruco::DICT_4X4_1000, ""},
                           {cv::aruco::DICT_5X5_1000, ""},
                           {cv::aruco::DICT_6X6_1000, ""},
                           {cv::aruco::DICT_7X7_1000, ""},
                           {cv::aruco::DICT_ARUCO_ORIGINAL, ""},
                           {cv::aruco::DICT_APRILTAG_16h5, "tag16h5"},
                           {cv::aruco::DICT_APRILTAG_25h9, "tag25h9"},
                           {cv::aruco::DICT_APRILTAG_36h10, "tag36h10"},
                           {cv::aruco::DICT_APRILTAG_36h11, "tag36h11"}};

std::string_view DictionaryName(int value) {
  return pose::ArucoDictionaries()[static_cast<std::size_t>(value)].name;
}

}  // namespace

std::string MarkersSeen::Kind() const {
  if (!family.empty()) return family + " AprilTags";
  const std::size_t last = dictionary.rfind('_');
  return (dictionary == "DICT_ARUCO_ORIGINAL" ? dictionary : dictionary.substr(0, last)) +
         " markers";
}

std::string MarkersSeen::Smallest() const {
  if (!family.empty()) return family;
  // The dictionaries of a kind are listed smallest first (pose::ArucoDictionaries).
  const std::size_t last = dictionary.rfind('_');
  const std::string prefix = dictionary.substr(0, last + 1);
  for (const pose::MarkerDictionary& d : pose::ArucoDictionaries()) {
    if (std::string_view(d.name).starts_with(prefix) && max_id < d.size) return std::string(d.name);
  }
  return dictionary;
}

std::optional<MarkersSeen> ProbeMarkers(const cv::Mat& gray, int min_markers) {
  const cv::Ptr<cv::aruco::DetectorParameters> parameters = cv::aruco::DetectorParameters::create();
  std::optional<MarkersSeen> best;
  for (const Kind& kind : kKinds) {
    std::vector<std::vector<cv::Point2f>> corners;
    std::vector<int> ids;
    cv::aruco::detectMarkers(gray, cv::aruco::getPredefinedDictionary(kind.dictionary), corners,
                             ids, parameters);
    const std::set<int> distinct(ids.begin(), ids.end());
    const int count = static_cast<int>(distinct.size());
    if (count < std::max(1, min_markers) || (best && count <= best->count)) continue;
    best = MarkersSeen{std::string(DictionaryName(kind.dictionary)), std::string(kind.family),
                       count, *distinct.begin(), *distinct.rbegin()};
  }
  return best;
}

}  // namespace hecal::vision
