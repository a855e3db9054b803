#include "visp_camera_xml.h"

#include <tinyxml2.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include "import_internal.h"

namespace hecal::io::internal {
namespace {

using import_internal::Fail;
using tinyxml2::XMLElement;

constexpr const char* kWithout = "perspectiveProjWithoutDistortion";
constexpr const char* kWith = "perspectiveProjWithDistortion";
constexpr const char* kLayout =
    "give a vpXmlParserCamera file: <root><camera><model><type>...</type><px>..<py>..<u0>..<v0>"
    "[<kud>..<kdu>..]</model></camera></root> (see docs/targets.md)";
constexpr long kLargestImageSide = 1 << 20;  // pixels; bounds the numbers, not real cameras

// Appended piece by piece: `"<" + std::string(...)` trips GCC 12's -Wrestrict false positive
// (GCC bug 105329, see core/error.h).
std::string Tag(const XMLElement& element) {
  std::string tag = "<";
  tag += element.Name();
  tag += '>';
  return tag;
}

// The element's text, trimmed; it must have no child elements.
std::string TextOf(const XMLElement& element, const std::string& source) {
  if (element.FirstChildElement()) {
    Fail(source, element.GetLineNum(), Tag(element) + " holds elements, not a value",
         "write the value alone, e.g. <px>600.5</px>");
  }
  const char* text = element.GetText();
  std::string_view value = text ? text : "";
  const size_t begin = value.find_first_not_of(" \t\r\n");
  if (begin == std::string_view::npos) return "";
  return std::string(value.substr(begin, value.find_last_not_of(" \t\r\n") - begin + 1));
}

double NumberOf(const XMLElement& element, const std::string& source) {
  const std::string text = TextOf(element, source);
  const std::optional<import_internal::Number> number = import_internal::ParseNumber(text);
  if (!number) {
    Fail(source, element.GetLineNum(),
         Tag(element) + " is " + import_internal::Quoted(text) + ", not a number",
         "write a plain decimal number with '.' as the decimal separator");
  }
  return number->value;
}

int SizeOf(const XMLElement& element, const std::string& source) {
  const double value = NumberOf(element, source);
  if (!(value >= 1.0) || value > kLargestImageSide || value != std::floor(value)) {
    Fail(source, element.GetLineNum(),
         Tag(element) + " is " + import_internal::Quoted(TextOf(element, source)) +
             ", not a whole number of pixels >= 1",
         "give the image size in pixels");
  }
  return static_cast<int>(value);
}

// One <model>: its type and values by element name, each once.
struct Model {
  std::string type;
  int line = 0;
  std::map<std::string, const XMLElement*> values;
};

Model ReadModel(const XMLElement& model_element, const std::string& source) {
  Model model;
  model.line = model_element.GetLineNum();
  const XMLElement* type = nullptr;
  for (const XMLElement* e = model_element.FirstChildElement(); e; e = e->NextSiblingElement()) {
    const std::string name = e->Name();
    if (name == "type") {
      if (type) {
        Fail(source, e->GetLineNum(), "<model> has two <type> elements",
             "give each model one type");
      }
      type = e;
      continue;
    }
    static constexpr std::string_view kValues[] = {"px", "py", "u0", "v0", "kud", "kdu"};
    if (std::find(std::begin(kValues), std::end(kValues), name) == std::end(kValues)) {
      Fail(source, e->GetLineNum(), "unknown element " + Tag(*e) + " in <model>",
           name.size() == 2 && name[0] == 'k'
               ? "hecal reads ViSP's perspective models (px, py, u0, v0, kud, kdu), not "
                 "Kannala-Brandt's k1..k5"
               : "use px, py, u0, v0 and, with distortion, kud and kdu");
    }
    if (!model.values.emplace(name, e).second) {
      Fail(source, e->GetLineNum(), "<model> has two " + Tag(*e) + " elements",
           "give each value once");
    }
  }
  if (!type) {
    Fail(source, model.line, "<model> has no <type>",
         std::string("add <type>") + kWith + "</type> or <type>" + kWithout + "</type>");
  }
  model.type = TextOf(*type, source);
  if (model.type != kWith && model.type != kWithout) {
    Fail(source, type->GetLineNum(),
         "model type " + import_internal::Quoted(model.type) +
             " is not one hecal reads (ViSP's perspective models, without or with kud distortion)",
         model.type == "ProjWithKannalaBrandtDistortion"
             ? "calibrate with ViSP's perspectiveProjWithDistortion model, or give hecal, "
               "OpenCV or ROS plumb_bob intrinsics"
             : std::string("use ") + kWith + " or " + kWithout);
  }
  const bool distortion = model.type == kWith;
  for (const char* name : {"px", "py", "u0", "v0", "kud", "kdu"}) {
    const bool wanted = distortion || name[0] != 'k';
    const bool present = model.values.count(name) > 0;
    if (wanted && !present) {
      Fail(source, model.line, model.type + " model has no <" + name + ">",
           std::string("add <") + name + ">..</" + name + "> to the model");
    }
    if (!wanted && present) {
      Fail(source, model.values.at(name)->GetLineNum(),
           std::string("<") + name + "> in a " + kWithout + " model",
           std::string("move it to a ") + kWith + " model, or remove it");
    }
  }
  return model;
}

struct Camera {
  std::string name;  // "" when the file has none
  VispCameraXml read;
};

Camera ReadCamera(const XMLElement& camera_element, const std::string& source) {
  Camera camera;
  pose::CameraModel& model = camera.read.file.camera;
  const XMLElement* size[2] = {nullptr, nullptr};
  std::optional<Model> models[2];  // without, with distortion
  for (const XMLElement* e = camera_element.FirstChildElement(); e; e = e->NextSiblingElement()) {
    const std::string name = e->Name();
    if (name == "name") {
      camera.name = TextOf(*e, source);
    } else if (name == "image_width" || name == "image_height") {
      size[name == "image_width" ? 0 : 1] = e;
    } else if (name == "model") {
      Model read = ReadModel(*e, source);
      std::optional<Model>& slot = models[read.type == kWith ? 1 : 0];
      if (slot) {
        Fail(source, read.line, "<camera> has two " + read.type + " models",
             "keep one model of each type");
      }
      slot = std::move(read);
    } else if (name != "subsampling_width" && name != "subsampling_height" &&
               name != "full_width" && name != "full_height" && name != "additional_information") {
      Fail(source, e->GetLineNum(), "unknown element " + Tag(*e) + " in <camera>",
           "use ViSP's elements: name, image_width, image_height, model, additional_information");
    }
  }
  if (size[0] || size[1]) {
    if (!size[0] || !size[1]) {
      Fail(source, (size[0] ? size[0] : size[1])->GetLineNum(),
           std::string("<camera> has ") + (size[0] ? "image_width" : "image_height") + " but no " +
               (size[0] ? "image_height" : "image_width"),
           "give both image sizes in pixels, or neither");
    }
    model.width = SizeOf(*size[0], source);
    model.height = SizeOf(*size[1], source);
  }
  if (!models[0] && !models[1]) {
    Fail(source, camera_element.GetLineNum(), "<camera> has no <model>",
         std::string("add a <model> with <type>") + kWith + "</type> or " + kWithout);
  }
  const Model& chosen = models[1] ? *models[1] : *models[0];
  double* targets[4] = {&model.fx, &model.fy, &model.cx, &model.cy};
  const char* names[4] = {"px", "py", "u0", "v0"};
  for (int k = 0; k < 4; ++k) {
    const XMLElement& element = *chosen.values.at(names[k]);
    *targets[k] = NumberOf(element, source);
    camera.read.lines[k] = element.GetLineNum();
  }
  const std::string label =
      source + ": ViSP camera" + (camera.name.empty() ? "" : " \"" + camera.name + "\"");
  if (models[1]) {
    const XMLElement& kud = *chosen.values.at("kud");
    model.distortion[0] = NumberOf(kud, source) + 0.0;  // ViSP writes "-0"; + 0.0 makes it 0
    if (!std::isfinite(model.distortion[0])) {
      Fail(source, kud.GetLineNum(), "<kud> is not finite", "give a finite kud");
    }
    NumberOf(*chosen.values.at("kdu"), source);  // must be a number too
    camera.read.file.notes.push_back(
        label + ": model " + kWith + ", read as plumb_bob k1 = kud = " +
        import_internal::Scientific(model.distortion[0]) + " (k2 = p1 = p2 = k3 = 0; kdu unused)" +
        (models[0] ? "; the model without distortion is ignored" : ""));
  } else {
    camera.read.file.notes.push_back(label + " has only the model " + kWithout +
                                     ": read as no distortion");
  }
  return camera;
}

bool SameCamera(const pose::CameraModel& a, const pose::CameraModel& b) {
  return a.fx == b.fx && a.fy == b.fy && a.cx == b.cx && a.cy == b.cy && a.width == b.width &&
         a.height == b.height && a.distortion == b.distortion;
}

std::string Describe(const Camera& camera) {
  const pose::CameraModel& model = camera.read.file.camera;
  std::string text = camera.name.empty() ? "(no name)" : import_internal::Quoted(camera.name);
  if (model.width > 0) {
    text += ' ';
    text += std::to_string(model.width);
    text += 'x';
    text += std::to_string(model.height);
  }
  return text;
}

}  // namespace

VispCameraXml ParseVispCameraXml(std::string_view text, const std::string& source) {
  tinyxml2::XMLDocument document;
  if (document.Parse(text.data(), text.size()) != tinyxml2::XML_SUCCESS) {
    const char* error = document.ErrorStr();
    Fail(source, document.ErrorLineNum(),
         std::string("not valid XML: ") + (error ? error : "parse error"),
         "fix the XML syntax (every element closed, one top element)");
  }
  const XMLElement* root = document.RootElement();
  if (!root || std::string_view(root->Name()) != "root") {
    Fail(source, root ? root->GetLineNum() : 0,
         "the XML's top element is " + (root ? Tag(*root) : std::string("missing")) +
             ", not ViSP's <root>",
         kLayout);
  }
  std::vector<Camera> cameras;
  for (const XMLElement* e = root->FirstChildElement(); e; e = e->NextSiblingElement()) {
    if (std::string_view(e->Name()) != "camera") {
      Fail(source, e->GetLineNum(), "unknown element " + Tag(*e) + " in <root>",
           "ViSP's camera file holds <camera> elements only");
    }
    cameras.push_back(ReadCamera(*e, source));
  }
  if (cameras.empty()) Fail(source, root->GetLineNum(), "<root> has no <camera>", kLayout);
  const bool identical = std::all_of(cameras.begin(), cameras.end(), [&](const Camera& camera) {
    return camera.name == cameras.front().name &&
           SameCamera(camera.read.file.camera, cameras.front().read.file.camera);
  });
  if (!identical) {
    std::string list;
    for (const Camera& camera : cameras) list += (list.empty() ? "" : ", ") + Describe(camera);
    Fail(source, 0,
         "has " + std::to_string(cameras.size()) + " different <camera> entries: " + list,
         "keep only the camera that took the images in the file");
  }
  return cameras.front().read;
}

}  // namespace hecal::io::internal
