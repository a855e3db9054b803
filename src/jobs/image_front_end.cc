// The image front end with its stages handed out: see image_front_end.h.
#include "hecal/jobs/image_front_end.h"

#include "hecal/io/image_pairing.h"
#include "hecal/jobs/image_set_text.h"

namespace hecal::jobs {

vision::ImageSet DetectImages(const vision::ImageSetOptions& options, const std::string& caller,
                              const JobCallbacks& callbacks) {
  vision::ImageSetProgress progress;
  progress.listed = [&](const vision::ImageSet& set) {
    if (!set.listing_note.empty()) callbacks.Note(set.listing_note);
    callbacks.Progress(ImageSetListedText(set, options, caller));
  };
  progress.detected = [&](const vision::ImageSet& set) {
    if (set.CountUsed() < vision::ImagesNeeded(options)) {
      callbacks.Progress(ImageTableText(set.images));
    }
  };
  progress.intrinsics = [&](const vision::ImageSet& set) {
    callbacks.Progress(ImageSetIntrinsicsText(set, options));
    if (!set.estimated) return;
    for (const std::string& warning : set.estimated->warnings) {
      callbacks.Warning("intrinsics: " + warning);
    }
  };
  progress.posed = [&](const vision::ImageSet& set) {
    callbacks.Progress(ImageTableText(set.images));
  };
  vision::ImageSet set = vision::DetectImageSet(options, progress);
  if (!set.fit_warning.empty()) callbacks.Warning(set.fit_warning);
  return set;
}

std::vector<Pose> RobotPosePerImage(const io::PoseTable& robot, const vision::ImageSet& set,
                                    const std::string& images_dir, const JobCallbacks& callbacks) {
  std::vector<io::StationImage> stations;
  for (const vision::ImageRecord& image : set.images) {
    stations.push_back({image.station, image.path, image.name});
  }
  return io::PairRobotWithStations(robot, stations, images_dir,
                                   [&callbacks](const std::string& note) { callbacks.Note(note); });
}

}  // namespace hecal::jobs
