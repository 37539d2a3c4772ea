#include "hovBatchSpec.h"

#include <vtk_jsoncpp.h> // VTK's JSON parser (jsoncpp)

#include <exception> // jsoncpp's nesting-limit exception

#include <cmath>   // std::isfinite
#include <fstream> // the spec file
#include <memory>  // the reader
#include <sstream> // messages

namespace hov
{
namespace
{
/// Collects "<field>: <problem>" messages while reading a JSON document.
struct Checker
{
  std::vector<std::string>& Errors;
  std::vector<std::string>& Warnings;

  void Error(const std::string& field, const std::string& what)
  {
    this->Errors.push_back(field + ": " + what);
  }

  static std::string Join(const std::string& parent, const std::string& key)
  {
    return parent.empty() ? key : parent + "." + key;
  }

  static std::string TypeName(const Json::Value& v)
  {
    switch (v.type())
    {
      case Json::nullValue: return "nothing (missing or null)";
      case Json::intValue:
      case Json::uintValue:
      case Json::realValue: return "a number";
      case Json::stringValue: return "a string";
      case Json::booleanValue: return "a boolean";
      case Json::arrayValue: return "an array";
      default: return "an object";
    }
  }

  /// Object check and unknown keys (keys starting with '_' are comments).
  bool Object(const Json::Value& v, const std::string& field, std::vector<std::string> allowed)
  {
    if (!v.isObject())
    {
      this->Error(field.empty() ? "(top level)" : field, "expected an object, got " + TypeName(v));
      return false;
    }
    for (const std::string& key : v.getMemberNames())
    {
      bool known = !key.empty() && key[0] == '_';
      for (const std::string& a : allowed)
      {
        known = known || key == a;
      }
      if (!known)
      {
        std::string list;
        for (const std::string& a : allowed)
        {
          list += (list.empty() ? "" : ", ") + a;
        }
        this->Error(Join(field, key), "unknown field (expected one of: " + list + ")");
      }
    }
    return true;
  }

  bool Number(const Json::Value& v, const std::string& field, double& out)
  {
    if (!v.isNumeric() || v.isBool())
    {
      this->Error(field, "expected a number, got " + TypeName(v));
      return false;
    }
    out = v.asDouble();
    if (!std::isfinite(out)) // jsoncpp reads 1e999 as infinity
    {
      this->Error(field, "expected a finite number");
      return false;
    }
    return true;
  }

  bool Positive(const Json::Value& v, const std::string& field, double& out)
  {
    if (!this->Number(v, field, out))
    {
      return false;
    }
    if (!(out > 0.0))
    {
      this->Error(field, "expected a positive number");
      return false;
    }
    return true;
  }

  bool Integer(const Json::Value& v, const std::string& field, int lo, int hi, int& out)
  {
    if (!v.isInt() || v.isBool())
    {
      this->Error(field, "expected an integer, got " + TypeName(v));
      return false;
    }
    out = v.asInt();
    if (out < lo || out > hi)
    {
      std::ostringstream s;
      s << "expected an integer in [" << lo << ", " << hi << "], got " << out;
      this->Error(field, s.str());
      return false;
    }
    return true;
  }

  bool String(const Json::Value& v, const std::string& field, std::string& out)
  {
    if (!v.isString())
    {
      this->Error(field, "expected a string, got " + TypeName(v));
      return false;
    }
    out = v.asString();
    return true;
  }

  bool Boolean(const Json::Value& v, const std::string& field, bool& out)
  {
    if (!v.isBool())
    {
      this->Error(field, "expected true or false, got " + TypeName(v));
      return false;
    }
    out = v.asBool();
    return true;
  }

  /// Exactly @p n numbers.
  bool Numbers(const Json::Value& v, const std::string& field, int n, double* out)
  {
    std::ostringstream s;
    if (!v.isArray())
    {
      s << "expected " << n << " numbers, got " << TypeName(v);
      this->Error(field, s.str());
      return false;
    }
    if (static_cast<int>(v.size()) != n)
    {
      s << "expected " << n << " numbers, got " << v.size();
      this->Error(field, s.str());
      return false;
    }
    for (int i = 0; i < n; ++i)
    {
      if (!this->Number(v[i], field + "[" + std::to_string(i) + "]", out[i]))
      {
        return false;
      }
    }
    return true;
  }

  /// One of @p names; the value is its index.
  bool Enum(const Json::Value& v, const std::string& field, const std::vector<std::string>& names,
    int& out)
  {
    std::string value;
    if (!this->String(v, field, value))
    {
      return false;
    }
    std::string list;
    for (size_t i = 0; i < names.size(); ++i)
    {
      if (names[i] == value)
      {
        out = static_cast<int>(i);
        return true;
      }
      list += (i ? ", " : "") + names[i];
    }
    this->Error(field, "unknown value '" + value + "' (expected one of: " + list + ")");
    return false;
  }

  /// A non-empty array of nodes of @p n numbers each, appended to @p out.
  void Nodes(const Json::Value& v, const std::string& field, int n, std::vector<double>& out)
  {
    if (!v.isArray() || v.empty())
    {
      this->Error(field, "expected a non-empty array of [" + std::string(n == 4 ? "s, r, g, b" : "s, a") +
          "] nodes, got " + (v.isArray() ? std::string("an empty array") : TypeName(v)));
      return;
    }
    for (Json::ArrayIndex i = 0; i < v.size(); ++i)
    {
      double node[4];
      if (this->Numbers(v[i], field + "[" + std::to_string(i) + "]", n, node))
      {
        out.insert(out.end(), node, node + n);
      }
    }
  }
};

std::string Resolve(const std::string& baseDir, const std::string& path)
{
  if (path.empty() || path[0] == '/' || baseDir.empty())
  {
    return path;
  }
  return baseDir + "/" + path;
}

void ParseCamera(Checker& c, const Json::Value& cam, BatchSpec& spec)
{
  if (!c.Object(cam, "camera",
        { "position", "focal_point", "view_up", "view_angle", "azimuth", "elevation", "roll",
          "zoom" }))
  {
    return;
  }
  const bool p = cam.isMember("position"), f = cam.isMember("focal_point");
  if (p != f)
  {
    c.Error(p ? "camera.focal_point" : "camera.position",
      "required when camera." + std::string(p ? "position" : "focal_point") + " is given");
  }
  spec.HasPosition = p && f;
  if (p)
  {
    c.Numbers(cam["position"], "camera.position", 3, spec.Position);
  }
  if (f)
  {
    c.Numbers(cam["focal_point"], "camera.focal_point", 3, spec.FocalPoint);
  }
  if ((spec.HasViewUp = cam.isMember("view_up")))
  {
    c.Numbers(cam["view_up"], "camera.view_up", 3, spec.ViewUp);
  }
  if ((spec.HasViewAngle = cam.isMember("view_angle")) &&
    c.Positive(cam["view_angle"], "camera.view_angle", spec.ViewAngle) && spec.ViewAngle >= 180.0)
  {
    c.Error("camera.view_angle", "expected degrees in (0, 180)");
  }
  if ((spec.HasAzimuth = cam.isMember("azimuth")))
  {
    c.Number(cam["azimuth"], "camera.azimuth", spec.Azimuth);
  }
  if ((spec.HasElevation = cam.isMember("elevation")))
  {
    c.Number(cam["elevation"], "camera.elevation", spec.Elevation);
  }
  if ((spec.HasRoll = cam.isMember("roll")))
  {
    c.Number(cam["roll"], "camera.roll", spec.Roll);
  }
  if ((spec.HasZoom = cam.isMember("zoom")))
  {
    c.Positive(cam["zoom"], "camera.zoom", spec.Zoom);
  }
}

void ParseTransferFunction(Checker& c, const Json::Value& tf, BatchSpec& spec)
{
  if (!c.Object(tf, "transfer_function",
        { "color", "opacity", "unit_distance", "opacity_semantics", "gpu_opacity_tolerance",
          "emission_model", "emission_scale" }))
  {
    return;
  }
  c.Nodes(tf["color"], "transfer_function.color", 4, spec.ColorNodes);
  c.Nodes(tf["opacity"], "transfer_function.opacity", 2, spec.OpacityNodes);
  if (tf.isMember("unit_distance"))
  {
    c.Positive(tf["unit_distance"], "transfer_function.unit_distance", spec.UnitDistance);
  }
  if (tf.isMember("opacity_semantics"))
  {
    c.Enum(tf["opacity_semantics"], "transfer_function.opacity_semantics",
      { "gpu_compatible", "vtk_unstructured", "raw_extinction" }, spec.OpacitySemantics);
  }
  if (tf.isMember("gpu_opacity_tolerance"))
  {
    c.Positive(
      tf["gpu_opacity_tolerance"], "transfer_function.gpu_opacity_tolerance", spec.GPUOpacityTolerance);
  }
  if (tf.isMember("emission_model"))
  {
    c.Enum(tf["emission_model"], "transfer_function.emission_model",
      { "williams_max", "wilhelms_van_gelder" }, spec.EmissionModel);
  }
  if (tf.isMember("emission_scale"))
  {
    c.Number(tf["emission_scale"], "transfer_function.emission_scale", spec.EmissionScale);
  }
}

void ParseFeatures(Checker& c, const Json::Value& root, BatchSpec& spec)
{
  if (root.isMember("isosurfaces"))
  {
    const Json::Value& iso = root["isosurfaces"];
    if (!iso.isArray())
    {
      c.Error("isosurfaces", "expected an array of objects, got " + Checker::TypeName(iso));
    }
    for (Json::ArrayIndex i = 0; iso.isArray() && i < iso.size(); ++i)
    {
      const std::string f = "isosurfaces[" + std::to_string(i) + "]";
      double s[5] = { 0, 1, 1, 1, 1 };
      if (c.Object(iso[i], f, { "value", "color", "opacity" }))
      {
        c.Number(iso[i]["value"], f + ".value", s[0]);
        if (iso[i].isMember("color"))
        {
          c.Numbers(iso[i]["color"], f + ".color", 3, s + 1);
        }
        if (iso[i].isMember("opacity"))
        {
          c.Number(iso[i]["opacity"], f + ".opacity", s[4]);
        }
        spec.Isosurfaces.insert(spec.Isosurfaces.end(), s, s + 5);
      }
    }
  }
  if (!root.isMember("clipping") || !c.Object(root["clipping"], "clipping", { "planes", "view_depth_range" }))
  {
    return;
  }
  const Json::Value& clip = root["clipping"];
  if (clip.isMember("planes"))
  {
    const Json::Value& planes = clip["planes"];
    if (!planes.isArray())
    {
      c.Error("clipping.planes", "expected an array of objects, got " + Checker::TypeName(planes));
    }
    for (Json::ArrayIndex i = 0; planes.isArray() && i < planes.size(); ++i)
    {
      const std::string f = "clipping.planes[" + std::to_string(i) + "]";
      double p[6];
      if (c.Object(planes[i], f, { "origin", "normal" }) &&
        c.Numbers(planes[i]["origin"], f + ".origin", 3, p) &&
        c.Numbers(planes[i]["normal"], f + ".normal", 3, p + 3))
      {
        spec.ClipPlanes.insert(spec.ClipPlanes.end(), p, p + 6);
      }
    }
  }
  if ((spec.ViewDepthClipping = clip.isMember("view_depth_range")) &&
    c.Numbers(clip["view_depth_range"], "clipping.view_depth_range", 2, spec.ViewDepthRange) &&
    !(spec.ViewDepthRange[0] < spec.ViewDepthRange[1]))
  {
    c.Error("clipping.view_depth_range", "expected [near, far] with near < far");
  }
}

void ParseInputOutput(Checker& c, const Json::Value& root, const std::string& baseDir, BatchSpec& spec)
{
  if (c.String(root["data"], "data", spec.Data))
  {
    spec.Data = Resolve(baseDir, spec.Data);
  }
  const Json::Value& array = root["array"];
  if (array.isString())
  {
    spec.ArrayName = array.asString();
  }
  else if (c.Object(array, "array", { "name", "component", "association" }))
  {
    c.String(array["name"], "array.name", spec.ArrayName);
    if (array.isMember("component"))
    {
      c.Integer(array["component"], "array.component", -1, 1 << 20, spec.ArrayComponent);
    }
    int association = 0;
    if (array.isMember("association") &&
      c.Enum(array["association"], "array.association", { "point", "cell" }, association))
    {
      spec.CellArray = association == 1;
    }
  }
  const Json::Value& out = root["output"];
  if (c.Object(out, "output", { "vti", "png" }))
  {
    // Outputs are relative to the current directory (data: to the spec's folder).
    if (out.isMember("vti"))
    {
      c.String(out["vti"], "output.vti", spec.OutputVTI);
    }
    if (out.isMember("png"))
    {
      c.String(out["png"], "output.png", spec.OutputPNG);
    }
    if (!out.isMember("vti") && !out.isMember("png"))
    {
      c.Error("output", "expected at least one of vti, png");
    }
  }
}
}

namespace
{
/// Offset of the first byte of @p text that is not part of well-formed UTF-8
/// (RFC 3629: no overlong forms, no surrogates, at most U+10FFFF), or npos.
size_t InvalidUTF8(const std::string& text)
{
  const auto* p = reinterpret_cast<const unsigned char*>(text.data());
  const size_t n = text.size();
  for (size_t i = 0; i < n;)
  {
    const unsigned char b = p[i];
    int extra = 0;
    unsigned lo = 0x80, hi = 0xBF; // range of the first continuation byte
    if (b < 0x80)
    {
      ++i;
      continue;
    }
    else if (b >= 0xC2 && b <= 0xDF)
    {
      extra = 1;
    }
    else if (b >= 0xE0 && b <= 0xEF)
    {
      extra = 2;
      lo = b == 0xE0 ? 0xA0 : 0x80;
      hi = b == 0xED ? 0x9F : 0xBF;
    }
    else if (b >= 0xF0 && b <= 0xF4)
    {
      extra = 3;
      lo = b == 0xF0 ? 0x90 : 0x80;
      hi = b == 0xF4 ? 0x8F : 0xBF;
    }
    else
    {
      return i;
    }
    if (i + extra >= n) // truncated sequence
    {
      return i;
    }
    for (int k = 1; k <= extra; ++k)
    {
      const unsigned c = p[i + k];
      if (c < (k == 1 ? lo : 0x80) || c > (k == 1 ? hi : 0xBF))
      {
        return i;
      }
    }
    i += extra + 1;
  }
  return std::string::npos;
}
}

bool ParseBatchSpec(const std::string& text, const std::string& baseDir, BatchSpec& spec,
  std::vector<std::string>& errors, std::vector<std::string>& warnings)
{
  Checker c{ errors, warnings };
  const size_t bad = InvalidUTF8(text);
  if (bad != std::string::npos)
  {
    c.Error("(file)", "not valid JSON: not UTF-8 text (byte " + std::to_string(bad) + ")");
    return false;
  }
  Json::Value root;
  std::string parseErrors;
  Json::CharReaderBuilder builder;
  builder["collectComments"] = false;
  std::unique_ptr<Json::CharReader> reader(builder.newCharReader());
  bool parsed = false;
  try
  {
    parsed = reader->parse(text.data(), text.data() + text.size(), &root, &parseErrors);
  }
  catch (const std::exception& e)
  {
    // jsoncpp throws past its nesting limit (stackLimit, 1000 levels).
    parseErrors = e.what();
  }
  if (!parsed)
  {
    c.Error("(file)", "not valid JSON: " + parseErrors);
    return false;
  }
  if (!c.Object(root, "",
        { "data", "array", "image", "background", "camera", "projection", "transfer_function",
          "isosurfaces", "clipping", "render_mode", "ray_cast_tolerance", "integration",
          "cell_ordering", "output" }))
  {
    return false;
  }
  ParseInputOutput(c, root, baseDir, spec);
  if (root.isMember("image") && c.Object(root["image"], "image", { "width", "height" }))
  {
    c.Integer(root["image"]["width"], "image.width", 1, 16384, spec.Width);
    c.Integer(root["image"]["height"], "image.height", 1, 16384, spec.Height);
  }
  if (root.isMember("background"))
  {
    c.Numbers(root["background"], "background", 3, spec.Background);
  }
  if (root.isMember("camera"))
  {
    ParseCamera(c, root["camera"], spec);
  }
  const Json::Value proj = root.get("projection", Json::Value());
  if (root.isMember("projection") && c.Object(proj, "projection", { "type", "parallel_scale" }))
  {
    int type = 0;
    if (proj.isMember("type") &&
      c.Enum(proj["type"], "projection.type", { "perspective", "orthographic" }, type))
    {
      spec.Orthographic = type == 1;
    }
    if ((spec.HasParallelScale = proj.isMember("parallel_scale")))
    {
      c.Positive(proj["parallel_scale"], "projection.parallel_scale", spec.ParallelScale);
    }
  }
  ParseTransferFunction(c, root["transfer_function"], spec);
  ParseFeatures(c, root, spec);
  if (root.isMember("render_mode"))
  {
    c.Enum(root["render_mode"], "render_mode", { "cpu_accurate", "opengl_projection", "ray_cast" },
      spec.RenderMode);
  }
  if (root.isMember("ray_cast_tolerance") &&
    c.Positive(root["ray_cast_tolerance"], "ray_cast_tolerance", spec.RayCastTolerance) &&
    (spec.RayCastTolerance < 1e-12 || spec.RayCastTolerance > 0.1))
  {
    c.Error("ray_cast_tolerance", "expected a number in [1e-12, 0.1]");
  }
  if (root.isMember("integration"))
  {
    c.Enum(root["integration"], "integration", { "exact", "approximate" }, spec.Integration);
  }
  if (root.isMember("cell_ordering"))
  {
    c.Enum(root["cell_ordering"], "cell_ordering", { "visibility_sort", "per_pixel_sort" },
      spec.CellOrdering);
  }
  if (spec.RenderMode == 1 && (!spec.Isosurfaces.empty() || !spec.ClipPlanes.empty() || spec.ViewDepthClipping))
  {
    c.Error("render_mode", "opengl_projection does not support isosurfaces or clipping (use cpu_accurate)");
  }
  if (spec.RenderMode == 2 && !spec.Isosurfaces.empty())
  {
    c.Error("render_mode", "ray_cast does not support isosurfaces (use cpu_accurate)");
  }
  return errors.empty();
}

bool ReadBatchSpec(const std::string& path, BatchSpec& spec, std::vector<std::string>& errors,
  std::vector<std::string>& warnings)
{
  std::ifstream in(path);
  if (!in)
  {
    errors.push_back("(file): cannot read '" + path + "'");
    return false;
  }
  std::stringstream text;
  text << in.rdbuf();
  const size_t slash = path.find_last_of('/');
  const std::string baseDir = slash == std::string::npos ? "." : path.substr(0, slash);
  return ParseBatchSpec(text.str(), baseDir.empty() ? "/" : baseDir, spec, errors, warnings);
}
}
