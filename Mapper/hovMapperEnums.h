/**
 * @file    hovMapperEnums.h
 * @brief   vtkHighOrderVolumeMapper's public enums as the hov enums the render
 *          modes read (hov::FrameSettings): one table per enum, indexed by the
 *          public value, each pinned by a static_assert. Private to the facade
 *          (vtkHighOrderVolumeMapper.cxx, FrameSettingsOf); not installed.
 */
#ifndef hovMapperEnums_h
#define hovMapperEnums_h

#include "hovBlendModes.h"          // BlendMode
#include "hovFrameSettings.h"       // the hov enums
#include "vtkHighOrderVolumeMapper.h"

#include <algorithm> // std::min, std::max
#include <cstddef>   // size_t

namespace hov
{
namespace mapper_enums
{
/// Entry @p value of @p table (the public enum's value: the static_asserts
/// below pin the order), clamped as the public setters clamp.
template <typename Enum, size_t N>
Enum Convert(const Enum (&table)[N], int value)
{
  return table[std::min(std::max(value, 0), static_cast<int>(N) - 1)];
}

using Mapper = vtkHighOrderVolumeMapper;
// The public enums, converted once (FrameSettingsOf) into the hov enums the
// render modes read; each table is indexed by the public value.
constexpr hov::RenderMode RenderModes[] = { hov::RenderMode::CPUAccurate,
  hov::RenderMode::OpenGLProjection, hov::RenderMode::RayCast };
static_assert(Mapper::CPU_ACCURATE == 0 && Mapper::OPENGL_PROJECTION == 1 && Mapper::RAY_CAST == 2,
  "RenderModes");
constexpr hov::OpacitySemantics Semantics[] = { hov::OpacitySemantics::GPUCompatible,
  hov::OpacitySemantics::VTKUnstructured, hov::OpacitySemantics::RawExtinction };
static_assert(Mapper::GPU_COMPATIBLE == 0 && Mapper::VTK_UNSTRUCTURED == 1 &&
    Mapper::RAW_EXTINCTION == 2,
  "Semantics");
constexpr hov::EmissionModel Emissions[] = { hov::EmissionModel::WilliamsMax,
  hov::EmissionModel::WilhelmsVanGelder };
static_assert(Mapper::WILLIAMS_MAX == 0 && Mapper::WILHELMS_VAN_GELDER == 1, "Emissions");
constexpr hov::SegmentMethod Methods[] = { hov::SegmentMethod::Exact,
  hov::SegmentMethod::Approximate };
static_assert(Mapper::EXACT == 0 && Mapper::APPROXIMATE == 1, "Methods");
constexpr hov::CellOrdering Orderings[] = { hov::CellOrdering::VisibilitySort,
  hov::CellOrdering::PerPixelSort };
static_assert(Mapper::VISIBILITY_SORT == 0 && Mapper::PER_PIXEL_SORT == 1, "Orderings");
constexpr hov::VectorMode VectorModes[] = { hov::VectorMode::Magnitude, hov::VectorMode::Component };
static_assert(Mapper::MAGNITUDE == 0 && Mapper::COMPONENT == 1, "VectorModes");
constexpr hov::ProjectionColorMethod ColorMethods[] = {
  hov::ProjectionColorMethod::InterpolatedOpacity, hov::ProjectionColorMethod::AverageColor,
  hov::ProjectionColorMethod::TableColor, hov::ProjectionColorMethod::ExactColor
};
static_assert(Mapper::INTERPOLATED_OPACITY == 0 && Mapper::AVERAGE_COLOR == 1 &&
    Mapper::TABLE_COLOR == 2 && Mapper::EXACT_COLOR == 3,
  "ColorMethods");
constexpr hov::ProjectionOrder Orders[] = { hov::ProjectionOrder::Exact,
  hov::ProjectionOrder::Approximate };
static_assert(Mapper::EXACT_ORDER == 0 && Mapper::APPROXIMATE_ORDER == 1, "Orders");
constexpr hov::OpacityLookup Lookups[] = { hov::OpacityLookup::Texture,
  hov::OpacityLookup::Analytic };
static_assert(Mapper::OPACITY_TEXTURE == 0 && Mapper::OPACITY_ANALYTIC == 1, "Lookups");
constexpr hov::BlendMode BlendModes[] = { hov::BlendMode::Composite,
  hov::BlendMode::MaximumIntensity, hov::BlendMode::MinimumIntensity,
  hov::BlendMode::AverageIntensity };
static_assert(Mapper::COMPOSITE_BLEND == 0 && Mapper::MAXIMUM_INTENSITY_BLEND == 1 &&
    Mapper::MINIMUM_INTENSITY_BLEND == 2 && Mapper::AVERAGE_INTENSITY_BLEND == 3,
  "BlendModes");
}
}

#endif
