#pragma once
// A log-log scatter plot of error against cost as a standalone SVG, written by hand: grey grid
// points, the Pareto front as a connected line, presets ringed and labelled, failed runs in a band
// above the plot.

#include <string>
#include <vector>

namespace accuracy {

struct PlotPoint {
    double cost = 0.0;   // x, > 0
    double error = 0.0;  // y; not finite: a failed run; zero: drawn at the bottom edge
    bool onFront = false;
    std::vector<std::string> presets;  // preset names at this point, if any
};

struct Plot {
    std::string title;
    std::string subtitle;
    std::string xLabel;
    std::string yLabel;
    std::vector<PlotPoint> points;
};

std::string renderSvg(const Plot& plot);

}  // namespace accuracy
