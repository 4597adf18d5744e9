// Umbrella header of the rasterd library: parse_scene -> plan -> render -> encode_png.
#pragma once

#include "raster/error.h"
#include "raster/image.h"
#include "raster/model.h"
#include "raster/plan.h"
#include "raster/png.h"
#include "raster/render.h"
#include "raster/scene.h"
#include "raster/utf8.h"
#include "raster/version.h"
