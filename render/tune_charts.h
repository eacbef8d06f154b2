// The charts of a tuning (plantsim tune): how each search's best score grew with its evaluations,
// and the score each evaluation got against each parameter's value.
#pragma once

#include <string>
#include <vector>

#include "render/figure.h"

namespace plantsim::render {

/// One search's scores in evaluation order; a candidate below the objective's floor (or whose
/// settings were refused) is not a point of the scale: `counted` false.
struct SearchScores {
  std::string label;
  Rgb colour;
  std::vector<double> score;
  std::vector<bool> counted;
  std::vector<std::vector<double>> values;  ///< per evaluation, per parameter
};

/// Best score so far against the evaluation's number, one line per search, each evaluation a dot,
/// the default settings' score as a horizontal line.
Image draw_convergence_chart(const std::vector<SearchScores>& searches, double default_score,
                             const std::string& title, const std::string& y_label,
                             int width_px = 1300, FigureLayout* layout = nullptr);

struct ParameterAxis {
  std::string name;
  double lo = 0, hi = 1;
  double default_value = 0, best_value = 0;
};

/// One panel per parameter: every evaluation's score against its value, the default and the
/// best value marked.
Image draw_parameter_scores(const std::vector<ParameterAxis>& parameters,
                            const std::vector<SearchScores>& searches, const std::string& y_label,
                            int width_px = 1300, FigureLayout* layout = nullptr);

}  // namespace plantsim::render
