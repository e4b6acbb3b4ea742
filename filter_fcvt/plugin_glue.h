#pragma once
// What the glue of each MeshLab (meshlab2020/, meshlab2022/) shares, as templates over that
// MeshLab's plugin interface and parameter list: the filter class of each filter, and the values
// a RichParameterList holds. Included by the glue after its MeshLab's interface header.
#include "fcvt_filters.h"

namespace fcvt_plugin::glue {

inline FilterId filterId(int id) { return static_cast<FilterId>(id); }

//! The filter's class in the enum of `Interface` (MeshFilterInterface or FilterPlugin).
template <class Interface>
typename Interface::FilterClass filterClass(FilterId filter)
{
    switch (filterKind(filter)) {
    case FilterKind::Remeshing: return Interface::Remeshing;
    case FilterKind::Normal: return Interface::Normal;
    case FilterKind::MeasureAndVertexColouring:
    default: return typename Interface::FilterClass(Interface::Measure | Interface::VertexColoring);
    }
}

//! The values of a RichParameterList, read alike in every MeshLab but for a mesh parameter
//! (getMesh, the glue's own). Floats as typed (typedValue).
template <class ParameterList>
class RichValues : public ParamValues {
public:
    explicit RichValues(const ParameterList& par) : par_(par) {}
    bool hasParameter(const char* name) const override { return par_.hasParameter(name); }
    bool isBool(const char* name) const override { return par_.getParameterByName(name).value().isBool(); }
    int getInt(const char* name) const override { return par_.getInt(name); }
    double getFloat(const char* name) const override { return typedValue(par_.getFloat(name)); }
    bool getBool(const char* name) const override { return par_.getBool(name); }
    int getEnum(const char* name) const override { return par_.getEnum(name); }
    double getAbsPerc(const char* name) const override { return typedValue(par_.getAbsPerc(name)); }

protected:
    const ParameterList& par_;
};

}  // namespace fcvt_plugin::glue
