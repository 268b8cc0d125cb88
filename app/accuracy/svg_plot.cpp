#include "accuracy/svg_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <string_view>

namespace accuracy {

namespace {

constexpr double kWidth = 760.0, kHeight = 520.0;
constexpr double kLeft = 96.0, kRight = 24.0, kTop = 92.0, kBottom = 72.0;
constexpr double kFailedBandY = 74.0;  // failed runs are drawn on this line, above the plot area

std::string number(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.1f", v);
    return buffer;
}

std::string escape(const std::string& text) {
    std::string out;
    for (char c : text) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            default: out += c;
        }
    }
    return out;
}

// "0.01", "250", or m·10^e with a superscript exponent outside [1e-3, 1e4).
std::string tickLabel(int mantissa, int exponent) {
    const double v = mantissa * std::pow(10.0, exponent);
    if (exponent >= -3 && exponent <= 3) {
        char buffer[32];
        std::snprintf(buffer, sizeof buffer, "%.*f", std::max(0, -exponent), v);
        return buffer;
    }
    const std::string power = "10<tspan dy=\"-6\" font-size=\"9\">" + std::string(exponent < 0 ? "−" : "") +
                              std::to_string(std::abs(exponent)) + "</tspan>";
    return mantissa == 1 ? power : std::to_string(mantissa) + "·" + power;
}

struct LogAxis {
    int lowDecade = 0, highDecade = 1;
    double from = 0.0, to = 1.0;  // pixel positions of lowDecade and highDecade

    static LogAxis fit(double minValue, double maxValue, double from, double to) {
        LogAxis a;
        a.lowDecade = static_cast<int>(std::floor(std::log10(minValue)));
        a.highDecade = static_cast<int>(std::ceil(std::log10(maxValue)));
        if (a.highDecade <= a.lowDecade) a.highDecade = a.lowDecade + 1;
        a.from = from;
        a.to = to;
        return a;
    }
    double map(double v) const {
        const double t = (std::log10(v) - lowDecade) / (highDecade - lowDecade);
        return from + t * (to - from);
    }
    bool labelsIntermediate() const { return highDecade - lowDecade <= 2; }
};

const std::map<std::string, std::string> kPresetColours{
    {"fast", "#d62728"}, {"balanced", "#2ca02c"}, {"accurate", "#7b3fb5"}};

std::string presetColour(const std::string& name) {
    const auto it = kPresetColours.find(name);
    return it == kPresetColours.end() ? "#ff7f0e" : it->second;
}

}  // namespace

std::string renderSvg(const Plot& plot) {
    const double plotLeft = kLeft, plotRight = kWidth - kRight, plotTop = kTop, plotBottom = kHeight - kBottom;

    double minCost = std::numeric_limits<double>::infinity(), maxCost = 0.0;
    double minError = std::numeric_limits<double>::infinity(), maxError = 0.0;
    bool anyFailed = false, anyZero = false;
    for (const PlotPoint& p : plot.points) {
        minCost = std::min(minCost, p.cost);
        maxCost = std::max(maxCost, p.cost);
        if (!std::isfinite(p.error)) {
            anyFailed = true;
        } else if (p.error <= 0.0) {
            anyZero = true;
        } else {
            minError = std::min(minError, p.error);
            maxError = std::max(maxError, p.error);
        }
    }
    if (!(minError <= maxError)) minError = maxError = 1.0;
    const LogAxis x = LogAxis::fit(minCost, maxCost, plotLeft, plotRight);
    const LogAxis y = LogAxis::fit(minError, maxError, plotBottom, plotTop);
    auto yOf = [&](double error) {
        if (!std::isfinite(error)) return kFailedBandY;
        return error <= 0.0 ? plotBottom : y.map(error);
    };

    std::string svg;
    auto add = [&svg](const std::string& s) { svg += s + "\n"; };
    add("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + number(kWidth) + "\" height=\"" + number(kHeight) +
        "\" viewBox=\"0 0 " + number(kWidth) + " " + number(kHeight) +
        "\" font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\" font-size=\"12\">");
    add("<rect width=\"100%\" height=\"100%\" fill=\"white\"/>");
    add("<text x=\"" + number(kWidth / 2) + "\" y=\"24\" text-anchor=\"middle\" font-size=\"16\" font-weight=\"bold\">" +
        escape(plot.title) + "</text>");
    add("<text x=\"" + number(kWidth / 2) + "\" y=\"44\" text-anchor=\"middle\" font-size=\"11\" fill=\"#444\">" + escape(plot.subtitle) +
        "</text>");

    // Grid lines and ticks: every decade labelled; 2 and 5 labelled too on short axes.
    for (int d = x.lowDecade; d <= x.highDecade; ++d) {
        for (int m = 1; m <= 9 && (m == 1 || d < x.highDecade); ++m) {
            const double px = x.map(m * std::pow(10.0, d));
            const bool labelled = m == 1 || (x.labelsIntermediate() && (m == 2 || m == 5));
            add("<line x1=\"" + number(px) + "\" y1=\"" + number(plotTop) + "\" x2=\"" + number(px) + "\" y2=\"" +
                number(plotBottom) + "\" stroke=\"" + (m == 1 ? "#d0d0d0" : "#eeeeee") + "\"/>");
            if (labelled)
                add("<text x=\"" + number(px) + "\" y=\"" + number(plotBottom + 18) + "\" text-anchor=\"middle\">" +
                    tickLabel(m, d) + "</text>");
        }
    }
    for (int d = y.lowDecade; d <= y.highDecade; ++d) {
        for (int m = 1; m <= 9 && (m == 1 || d < y.highDecade); ++m) {
            const double py = y.map(m * std::pow(10.0, d));
            const bool labelled = m == 1 || (y.labelsIntermediate() && (m == 2 || m == 5));
            add("<line x1=\"" + number(plotLeft) + "\" y1=\"" + number(py) + "\" x2=\"" + number(plotRight) + "\" y2=\"" +
                number(py) + "\" stroke=\"" + (m == 1 ? "#d0d0d0" : "#eeeeee") + "\"/>");
            if (labelled)
                add("<text x=\"" + number(plotLeft - 8) + "\" y=\"" + number(py + 4) + "\" text-anchor=\"end\">" +
                    tickLabel(m, d) + "</text>");
        }
    }
    add("<rect x=\"" + number(plotLeft) + "\" y=\"" + number(plotTop) + "\" width=\"" + number(plotRight - plotLeft) +
        "\" height=\"" + number(plotBottom - plotTop) + "\" fill=\"none\" stroke=\"#333\"/>");
    add("<text x=\"" + number((plotLeft + plotRight) / 2) + "\" y=\"" + number(kHeight - 24) +
        "\" text-anchor=\"middle\">" + escape(plot.xLabel) + "</text>");
    add("<text transform=\"translate(22 " + number((plotTop + plotBottom) / 2) + ") rotate(-90)\" text-anchor=\"middle\">" +
        escape(plot.yLabel) + "</text>");
    if (anyFailed)
        add("<text x=\"" + number(plotLeft - 8) + "\" y=\"" + number(kFailedBandY + 4) +
            "\" text-anchor=\"end\" fill=\"#a00\">failed</text>");
    if (anyZero)
        add("<text x=\"" + number(plotLeft + 4) + "\" y=\"" + number(plotBottom - 4) +
            "\" fill=\"#666\" font-size=\"10\">error 0 drawn on the bottom edge</text>");

    // All points, grey; failed runs as crosses in the band above.
    for (const PlotPoint& p : plot.points) {
        const double px = x.map(p.cost), py = yOf(p.error);
        if (!std::isfinite(p.error))
            add("<path d=\"M" + number(px - 3) + " " + number(py - 3) + "l6 6m0 -6l-6 6\" stroke=\"#a00\" stroke-width=\"1.2\"/>");
        else
            add("<circle cx=\"" + number(px) + "\" cy=\"" + number(py) + "\" r=\"2.6\" fill=\"#8c8c8c\" fill-opacity=\"0.55\"/>");
    }

    // The front, cheapest first, as a connected line.
    std::vector<const PlotPoint*> front;
    for (const PlotPoint& p : plot.points)
        if (p.onFront) front.push_back(&p);
    std::sort(front.begin(), front.end(), [](const PlotPoint* a, const PlotPoint* b) { return a->cost < b->cost; });
    std::string polyline;
    for (const PlotPoint* p : front) polyline += number(x.map(p->cost)) + "," + number(yOf(p->error)) + " ";
    add("<polyline points=\"" + polyline + "\" fill=\"none\" stroke=\"#1f77b4\" stroke-width=\"2\"/>");
    for (const PlotPoint* p : front)
        add("<circle cx=\"" + number(x.map(p->cost)) + "\" cy=\"" + number(yOf(p->error)) + "\" r=\"3.4\" fill=\"#1f77b4\"/>");

    // Presets: a coloured ring and the name beside it, fast's on the left (it is the cheapest, the
    // others lie to its right); labels of presets sharing a point are stacked.
    for (const PlotPoint& p : plot.points) {
        const double px = x.map(p.cost), py = yOf(p.error);
        for (std::size_t i = 0; i < p.presets.size(); ++i) {
            const std::string colour = presetColour(p.presets[i]);
            add("<circle cx=\"" + number(px) + "\" cy=\"" + number(py) + "\" r=\"" + number(6.5 + 3.0 * static_cast<double>(i)) +
                "\" fill=\"none\" stroke=\"" + colour + "\" stroke-width=\"2\"/>");
            const bool labelLeft = p.presets[i] == "fast" ? px > plotLeft + 60.0 : px > plotRight - 90.0;
            const double ly = py + 4.0 + 14.0 * static_cast<double>(i);
            const double offset = 10.0 + 3.0 * static_cast<double>(i);
            add("<text x=\"" + number(labelLeft ? px - offset : px + offset) + "\" y=\"" + number(ly) + "\" text-anchor=\"" +
                (labelLeft ? "end" : "start") + "\" fill=\"" + colour +
                "\" font-weight=\"bold\" stroke=\"white\" stroke-width=\"3\" paint-order=\"stroke\">" + escape(p.presets[i]) +
                "</text>");
        }
    }

    // Legend, above the plot on the right.
    const double lx = plotRight - 430.0, ly = 62.0;
    add("<circle cx=\"" + number(lx) + "\" cy=\"" + number(ly) + "\" r=\"2.6\" fill=\"#8c8c8c\"/>");
    add("<text x=\"" + number(lx + 8) + "\" y=\"" + number(ly + 4) + "\">grid point</text>");
    add("<line x1=\"" + number(lx + 80) + "\" y1=\"" + number(ly) + "\" x2=\"" + number(lx + 104) + "\" y2=\"" + number(ly) +
        "\" stroke=\"#1f77b4\" stroke-width=\"2\"/>");
    add("<text x=\"" + number(lx + 110) + "\" y=\"" + number(ly + 4) + "\">Pareto front</text>");
    double px = lx + 210.0;
    for (const char* name : {"fast", "balanced", "accurate"}) {
        add("<circle cx=\"" + number(px) + "\" cy=\"" + number(ly) + "\" r=\"5\" fill=\"none\" stroke=\"" + presetColour(name) +
            "\" stroke-width=\"2\"/>");
        add("<text x=\"" + number(px + 9) + "\" y=\"" + number(ly + 4) + "\">" + name + "</text>");
        px += 30.0 + 7.5 * static_cast<double>(std::string_view(name).size());
    }
    add("</svg>");
    return svg;
}

}  // namespace accuracy
