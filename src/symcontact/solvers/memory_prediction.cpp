#include "symcontact/solvers/memory_prediction.hpp"

#include <fstream>
#include <string>

#include "symcontact/fem/matrix_sink.hpp"
#include "symcontact/solvers/cholesky.hpp"

namespace symcontact {

double available_memory_bytes() {
  std::ifstream in("/proc/meminfo");
  std::string key, unit;
  double kib = 0;
  while (in >> key >> kib >> unit)
    if (key == "MemAvailable:") return kib * 1024.0;
  return -1.0;
}

FactorPrediction predict_factor(const EnergyTerm& energy, const std::vector<Index>& free_index, Index num_free) {
  ReducedTripletSink sink(free_index);
  energy.add_hessian(VectorXd::Zero(static_cast<Index>(free_index.size())), sink);  // K does not depend on u
  CholeskySolver chol;
  chol.analyze(sink.to_lower_matrix(num_free));
  return {chol.factor_nonzeros(), chol.factor_flops()};
}

double predict_factor_nonzeros(const EnergyTerm& energy, const std::vector<Index>& free_index, Index num_free) {
  return predict_factor(energy, free_index, num_free).nonzeros;
}

double predicted_direct_peak_bytes(double factor_nonzeros, double dofs, double contact_nodes) {
  return kFactorStorage * 8.0 * factor_nonzeros + kBytesPerDof * dofs + kDenseBytesPerEntry * contact_nodes * contact_nodes;
}

}  // namespace symcontact
