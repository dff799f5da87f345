#pragma once

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <ostream>
#include <string>
#include <vector>

#include "meshing/patch_mesh.h"
#include "radiosity/core/rgb.h"
#include "radiosity/output/tone_map.h"

namespace rad {

// Writes a solution (the layout of solution_polydata.h) as VTK XML PolyData, raw binary appended
// data with zlib compression, which ParaView opens. `sceneFile` is kept as field data "scene" so
// `radiosity view DIR` can find the scene's camera. Write to an AtomicFile opened in binary mode.
void writeSolutionVtp(std::ostream& out, const PatchMesh& mesh, const std::vector<Rgb>& radiosity,
                      const std::vector<Rgb>& unshot, const ToneMap& toneMap,
                      const std::string& sceneFile);
void writeSolutionVtp(std::ostream& out, vtkPolyData* solution);

// Reads solution.vtp back: first checks that the file has the layout writeSolutionVtp writes
// (solution_vtp_layout.h: VTK's reader is never given anything else), then that it holds every
// array of the solution with the right number of components and tuples and values the viewer
// can use; InputError naming the file otherwise.
vtkSmartPointer<vtkPolyData> readSolutionVtp(const std::string& path);

// The scene file recorded in the solution ("" when absent).
std::string solutionSceneFile(vtkPolyData* solution);

}  // namespace rad
