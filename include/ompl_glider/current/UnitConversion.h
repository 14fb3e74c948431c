#pragma once
/// @file UnitConversion.h
/// @brief The unit conversions moved to the io layer (ompl_glider/io/UnitConversion.h), where the readers of
/// forecasts and of a glider's observations both use them; this header keeps the old path working.
#include "ompl_glider/io/UnitConversion.h"
