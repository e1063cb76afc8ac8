// The two models of the turbulent fluctuation a texture particle sees (texture/turbulent_fluctuation.hpp):
// the paper's fresh draw every step, or an Ornstein-Uhlenbeck (Langevin) process.
#pragma once

namespace mistfall {

enum class FluctuationModel { Redrawn, Langevin };

}  // namespace mistfall
