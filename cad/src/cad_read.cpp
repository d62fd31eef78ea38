// Reading STEP / BREP / IGES files into one shape, with solid names, sewing of
// solid-less files, optional healing and the validity check.
#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESControl_Reader.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <ShapeFix_Solid.hxx>
#include <StepData_StepModel.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "cad_model.h"
#include "isolated_read.h"
#include "rdmesh/input_file.h"
#include "shape_healing.h"
#include "step_names.h"

namespace rdmesh::cad {
namespace {

int count(const TopoDS_Shape& s, TopAbs_ShapeEnum type) {
  int n = 0;
  for (TopExp_Explorer ex(s, type); ex.More(); ex.Next()) ++n;
  return n;
}

ReadShape read_iges(const std::string& path) {
  IGESControl_Reader reader;
  if (reader.ReadFile(path.c_str()) != IFSelect_RetDone) {
    throw InputError(path, "cannot parse the IGES file (corrupt or truncated?)");
  }
  if (reader.TransferRoots() == 0) throw InputError(path, "the IGES file holds no shape");
  ReadShape r;
  r.shape = reader.OneShape();
  r.log.push_back("IGES read, lengths in millimetres");
  return r;
}

ReadShape read_brep(const std::string& path) {
  check_brep_text(path);
  ReadShape r;
  BRep_Builder builder;
  if (!BRepTools::Read(r.shape, path.c_str(), builder) || r.shape.IsNull()) {
    throw InputError(path, "cannot parse the BREP file (corrupt or truncated?)");
  }
  r.log.push_back("BREP read (no unit: lengths as stored)");
  return r;
}

// Sews the faces of a solid-less shape; each closed shell becomes a solid.
void make_solids(ReadShape& r, const std::string& path) {
  if (count(r.shape, TopAbs_FACE) == 0)
    throw InputError(path, "the file holds no solid and no face");
  BRepBuilderAPI_Sewing sewing;
  sewing.Add(r.shape);
  sewing.Perform();
  TopoDS_Compound solids;
  BRep_Builder builder;
  builder.MakeCompound(solids);
  int closed = 0, open = 0;
  for (TopExp_Explorer ex(sewing.SewedShape(), TopAbs_SHELL); ex.More(); ex.Next()) {
    const TopoDS_Shell& shell = TopoDS::Shell(ex.Current());
    if (!BRep_Tool::IsClosed(shell)) {
      ++open;
      continue;
    }
    ShapeFix_Solid fix;
    builder.Add(solids, fix.SolidFromShell(shell));
    ++closed;
  }
  if (closed == 0) {
    throw InputError(path, "the file holds no solid: its " +
                               std::to_string(count(r.shape, TopAbs_FACE)) + " faces form " +
                               std::to_string(open) +
                               " open shell(s); rdmesh meshes closed volumes only");
  }
  r.log.push_back("no solid in the file: sewed its faces into " + std::to_string(closed) +
                  " closed shell(s)" +
                  (open ? ", ignored " + std::to_string(open) + " open shell(s)" : ""));
  r.shape = solids;
}

// Everything about reading that runs OpenCASCADE on the file's content, which
// may crash or loop on a malformed file: in a child process when isolated.
ReadShape read_content(const std::string& path, const std::string& ext, const CadOptions& options) {
  ReadShape r;
  try {
    if (ext == ".step" || ext == ".stp") {
      r = read_step_with_names(path);
    } else if (ext == ".iges" || ext == ".igs") {
      r = read_iges(path);
    } else {
      r = read_brep(path);
    }
    if (r.shape.IsNull()) throw InputError(path, "the file holds no shape");
    if (count(r.shape, TopAbs_SOLID) == 0) make_solids(r, path);
    if (options.heal) heal_shape(r, path);
    if (options.check_validity) {
      BRepCheck_Analyzer check(r.shape);
      if (!check.IsValid()) {
        throw InputError(path, std::string("invalid B-rep (BRepCheck_Analyzer)") +
                                   (options.heal ? " even after healing" : "; try --heal"));
      }
    }
    check_shape_geometry(r.shape, path);
  } catch (const Standard_Failure& e) {
    throw InputError(path, "OpenCASCADE failed to read the model: " + describe(e));
  }
  return r;
}

}  // namespace

ReadShape read_shape(const std::string& path, const CadOptions& options) {
  silence_opencascade();
  check_input_file(path);
  std::error_code ec;
  if (!std::ifstream(path).good()) throw InputError(path, "cannot open the file");
  if (std::filesystem::file_size(path, ec) == 0) throw InputError(path, "the file is empty");
  const std::string ext = lower_extension(path);
  std::string format;
  if (ext == ".step" || ext == ".stp") {
    format = "STEP";
  } else if (ext == ".iges" || ext == ".igs") {
    format = "IGES";
  } else if (ext == ".brep") {
    format = "BREP";
  } else {
    throw InputError(path, "not a CAD file extension: '" + ext + "'");
  }
  if (!options.isolate) return read_content(path, ext, options);
  return read_in_child(
      path, format, [&] { return read_content(path, ext, options); }, options);
}

void silence_opencascade() {
  // OpenCASCADE's translators print to stdout; our errors say what went wrong.
  static const bool silenced = [] {
    Message::DefaultMessenger()->ChangePrinters().Clear();
    return true;
  }();
  (void)silenced;
}

std::string describe(const Standard_Failure& e) {
  const char* message = e.GetMessageString();
  return std::string(e.DynamicType()->Name()) +
         (message && *message ? std::string(": ") + message : "");
}

}  // namespace rdmesh::cad
