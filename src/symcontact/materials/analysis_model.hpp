#pragma once
/// \file analysis_model.hpp
/// The kinematic model of a computation: 2D plane strain, 2D plane stress, or 3D.

namespace symcontact {

enum class AnalysisModel { kPlaneStrain, kPlaneStress, kThreeD };

}  // namespace symcontact
