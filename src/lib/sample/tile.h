/*
 * Tile transforms on the CPU: the definitions of cl/tile.cl, which the
 * OpenCL kernels share (see there for the why).
 */
#ifndef FRS_TILE_H
#define FRS_TILE_H

#include <stdint.h>

#include "base/rng.h"

#include "../../../cl/tile.cl"

#endif
