// Small models built with OpenCASCADE, for tests and the bundled samples.
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <IGESControl_Controller.hxx>
#include <IGESControl_Writer.hxx>
#include <Interface_Static.hxx>
#include <STEPControl_Writer.hxx>
#include <TopoDS_Compound.hxx>
#include <filesystem>
#include <gp_Ax2.hxx>

#include "cad_model.h"

namespace rdmesh {
namespace {

TopoDS_Shape make_shape(CadTestShape kind) {
  switch (kind) {
    case CadTestShape::box:
      return BRepPrimAPI_MakeBox(10, 20, 30).Shape();
    case CadTestShape::cylinder:
      return BRepPrimAPI_MakeCylinder(5, 12).Shape();
    case CadTestShape::box_minus_cylinder: {
      const TopoDS_Shape box = BRepPrimAPI_MakeBox(20, 20, 10).Shape();
      const TopoDS_Shape hole =
          BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(10, 10, -1), gp::DZ()), 4, 12).Shape();
      BRepAlgoAPI_Cut cut(box, hole);
      if (!cut.IsDone()) throw InternalError("box minus cylinder: the cut failed");
      return cut.Shape();
    }
    case CadTestShape::two_boxes: {
      TopoDS_Compound c;
      BRep_Builder b;
      b.MakeCompound(c);
      b.Add(c, BRepPrimAPI_MakeBox(10, 10, 10).Shape());
      b.Add(c, BRepPrimAPI_MakeBox(gp_Pnt(10, 0, 0), 10, 10, 10).Shape());
      return c;
    }
    case CadTestShape::sphere:
      return BRepPrimAPI_MakeSphere(10).Shape();
  }
  throw InternalError("unknown CadTestShape");
}

}  // namespace

std::unique_ptr<CadOracle> make_cad_test_oracle(CadTestShape kind) {
  try {
    cad::ReadShape read;
    read.shape = make_shape(kind);
    return std::make_unique<CadOracle>(cad::build_model(std::move(read), "test shape"));
  } catch (const Standard_Failure& e) {
    throw InternalError("building a test shape: " + cad::describe(e));
  }
}

void write_cad_test_shape(CadTestShape kind, const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  cad::silence_opencascade();
  try {
    const TopoDS_Shape shape = make_shape(kind);
    bool ok = false;
    if (ext == ".step" || ext == ".stp") {
      STEPControl_Writer writer;
      Interface_Static::SetCVal("write.step.unit", "MM");
      ok = writer.Transfer(shape, STEPControl_AsIs) == IFSelect_RetDone &&
           writer.Write(path.c_str()) == IFSelect_RetDone;
    } else if (ext == ".iges" || ext == ".igs") {
      IGESControl_Controller::Init();
      IGESControl_Writer writer("MM", 1);  // B-rep mode: faces, shells and solids
      if (writer.AddShape(shape)) {
        writer.ComputeModel();
        ok = writer.Write(path.c_str());
      }
    } else if (ext == ".brep") {
      ok = BRepTools::Write(shape, path.c_str());
    } else {
      throw OutputError(path + ": not a CAD extension");
    }
    if (!ok) throw OutputError(path + ": OpenCASCADE could not write the shape");
  } catch (const Standard_Failure& e) {
    throw OutputError(path + ": " + cad::describe(e));
  }
}

}  // namespace rdmesh
