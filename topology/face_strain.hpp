#pragma once
/// \file
/// Former home of edge_engineering_strain and face_edge_strain, now in edge_measures.hpp with the
/// other edge and face measures. Kept only for lib/simulation.cpp, which another branch edits;
/// remove it once that file includes topology/edge_measures.hpp.

#include "topology/edge_measures.hpp"
