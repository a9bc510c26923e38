// SPDX-License-Identifier: Apache-2.0
#include "peers/vtk_iso_surface.h"

#include <vtkFloatArray.h>
#include <vtkFlyingEdges3D.h>
#include <vtkImageData.h>
#include <vtkMarchingCubes.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataAlgorithm.h>
#include <vtkSMPTools.h>
#include <vtkSmartPointer.h>

namespace enteron::peers {

const char* vtk_filter_name(VtkFilter filter) {
    return filter == VtkFilter::flying_edges ? "vtkFlyingEdges3D" : "vtkMarchingCubes";
}

namespace {

// Either filter, set up alike: the iso-value, and no normals, gradients or scalars.
template <typename Filter>
vtkSmartPointer<vtkPolyDataAlgorithm> make_filter(vtkImageData* image, double iso) {
    auto filter = vtkSmartPointer<Filter>::New();
    filter->SetInputData(image);
    filter->SetValue(0, iso);
    filter->ComputeNormalsOff();
    filter->ComputeGradientsOff();
    filter->ComputeScalarsOff();
    return filter;
}

}  // namespace

struct VtkIsoSurface::Impl {
    vtkSmartPointer<vtkImageData> image = vtkSmartPointer<vtkImageData>::New();
    vtkSmartPointer<vtkFloatArray> scalars = vtkSmartPointer<vtkFloatArray>::New();
    vtkSmartPointer<vtkPolyDataAlgorithm> filter;
};

VtkIsoSurface::VtkIsoSurface(const DenseField& field, double iso, VtkFilter filter) : impl_(std::make_unique<Impl>()) {
    vtkSMPTools::Initialize(1);  // one core, like ours
    impl_->image->SetDimensions(field.nx, field.ny, field.nz);
    impl_->image->SetOrigin(field.origin[0], field.origin[1], field.origin[2]);
    impl_->image->SetSpacing(field.spacing, field.spacing, field.spacing);
    // A view of our values (save = 1: VTK never frees them); VTK's x-fastest order is ours.
    impl_->scalars->SetArray(const_cast<float*>(field.values.data()), vtkIdType(field.values.size()), 1);
    impl_->scalars->SetName("field");
    impl_->image->GetPointData()->SetScalars(impl_->scalars);
    impl_->filter = filter == VtkFilter::flying_edges ? make_filter<vtkFlyingEdges3D>(impl_->image, iso)
                                                      : make_filter<vtkMarchingCubes>(impl_->image, iso);
}

VtkIsoSurface::~VtkIsoSurface() = default;

std::size_t VtkIsoSurface::run() {
    impl_->filter->Modified();  // run again although the input did not change
    impl_->filter->Update();
    return std::size_t(impl_->filter->GetOutput()->GetNumberOfPolys());
}

}  // namespace enteron::peers
