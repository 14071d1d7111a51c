#pragma once
// Planted violation for the layering test: data/ must not know the virtual plant.
#include "data/Batch.h"
#include "plant/VirtualPlant.h"
