// conformesh.h — the umbrella header of all of conformesh: the three libraries' umbrella headers. Link
// conformesh::refine (which brings conformesh::embedding and conformesh::intrinsic) with CMake, or use
// `pkg-config --cflags --libs conformesh`. Installed with the refine library, the one that needs the other two.
#pragma once

#include "conformesh/intrinsic/intrinsic.h"
#include "conformesh/embedding/embedding.h"
#include "conformesh/refine/refine.h"
