#pragma once
// Fixture only: a legal include (plant/ may use data/).
#include "data/Batch.h"
