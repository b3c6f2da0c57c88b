#include "cosim/clearance/BoreDistortion.hpp"

#include "cosim/io/TextTable.hpp"
#include "cosim/io/VtuPointField.hpp"

#include <Eigen/QR>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <limits>
#include <map>
#include <numbers>
#include <stdexcept>

namespace flexehd::cosim {

namespace {

constexpr double kPi = std::numbers::pi;

std::string lower(std::string_view s) {
    std::string out(s);
    for (auto& c : out) c = char(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

/// A CSV table with a header: the column of each name, and the numeric rows with their lines.
struct Table {
    std::map<std::string, std::size_t> column;  // lower-case header name → index
    std::vector<std::vector<double>> rows;
    std::vector<int> lines;
    std::size_t width = 0;
};

/// `alternatives`: groups of column names of which the header must name exactly one each; those
/// columns must hold numbers in every row (other columns are not parsed).
Table readTable(const std::string& path, const std::string& headerHelp,
                const std::vector<std::vector<std::string>>& alternatives) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error(path + ": no such file or not readable");
    Table t;
    bool header = false;
    std::vector<std::size_t> numeric;  // parsed columns
    DataLines lines(in, /*skipByteOrderMark=*/true);
    while (lines.next()) {
        const int lineNo = lines.number();
        const std::string_view line = lines.text();
        const std::vector<std::string_view> f = splitFields(line);
        if (!header) {
            header = true;
            double dummy = 0.0;
            if (!f.empty() && parseNumber(f[0], dummy))
                throw std::runtime_error(fmt::format("{}:{}: the first line must be a header naming the columns: {}",
                                                     path, lineNo, headerHelp));
            for (std::size_t c = 0; c < f.size(); ++c) {
                const std::string name = lower(f[c]);
                if (!t.column.emplace(name, c).second)
                    throw std::runtime_error(fmt::format("{}:{}: column '{}' given twice", path, lineNo, name));
            }
            t.width = f.size();
            // Exactly one name of each alternative group.
            for (const auto& group : alternatives) {
                std::size_t found = 0;
                std::string names;
                for (const auto& n : group) {
                    names += (names.empty() ? "" : " or ") + n;
                    if (t.column.count(n)) ++found, numeric.push_back(t.column[n]);
                }
                if (found != 1)
                    throw std::runtime_error(fmt::format("{}:{}: the header needs {} column {}; expected: {}", path,
                                                         lineNo, found == 0 ? "a" : "only one", names, headerHelp));
            }
            continue;
        }
        if (f.size() != t.width)
            throw std::runtime_error(fmt::format("{}:{}: expected {} fields as in the header, got {}: '{}'", path,
                                                 lineNo, t.width, f.size(), line));
        std::vector<double> row(t.width, 0.0);
        for (std::size_t c : numeric)
            if (!parseNumber(f[c], row[c]))
                throw std::runtime_error(
                    fmt::format("{}:{}: expected a number in column {}, got '{}'", path, lineNo, c + 1, f[c]));
        t.rows.push_back(std::move(row));
        t.lines.push_back(lineNo);
    }
    if (!header)
        throw std::runtime_error(path + ": the file is empty (expected a header and rows: " + headerHelp + ")");
    if (t.rows.empty()) throw std::runtime_error(path + ": the table has a header but no rows");
    return t;
}

double get(const Table& t, const std::vector<double>& row, const std::string& name) { return row[t.column.at(name)]; }

}  // namespace

// ---- Fourier orders -----------------------------------------------------------------------

std::optional<TermProblem> checkFourierTerms(const std::vector<FourierTerm>& terms, double bore) {
    if (terms.empty()) return TermProblem{0, "no Fourier term given"};
    std::map<std::pair<double, int>, std::size_t> seen;
    for (std::size_t i = 0; i < terms.size(); ++i) {
        const FourierTerm& t = terms[i];
        if (t.order < 0 || t.order > 100)
            return TermProblem{i, fmt::format("expected an order from 0 to 100, got {}", t.order)};
        if (std::abs(t.amplitude) > 0.01 * bore)
            return TermProblem{i, fmt::format("an amplitude of {:g} m is above 1% of the bore ({:g} m): check the "
                                              "units (m)",
                                              t.amplitude, 0.01 * bore)};
        if (!std::isfinite(t.z) || !std::isfinite(t.phase) || !std::isfinite(t.amplitude))
            return TermProblem{i, "expected finite numbers"};
        const auto [it, fresh] = seen.emplace(std::make_pair(t.z, t.order), i);
        if (!fresh)
            return TermProblem{i, fmt::format("order {} at z = {:g} m is given twice", t.order, t.z), it->second};
    }
    return std::nullopt;
}

void sortFourierTerms(std::vector<FourierTerm>& terms) {
    std::stable_sort(terms.begin(), terms.end(), [](const FourierTerm& a, const FourierTerm& b) {
        return a.z < b.z || (a.z == b.z && a.order < b.order);
    });
}

std::vector<FourierTerm> readFourierTable(const std::string& path, double bore) {
    const std::string help =
        "z (m, liner frame) or depth (m below the liner top), order, amplitude (m), phase (rad) "
        "or phase_deg (deg)";
    const Table t = readTable(path, help, {{"z", "depth"}, {"order"}, {"amplitude"}, {"phase", "phase_deg"}});
    for (const auto& [name, c] : t.column)
        if (name != "z" && name != "depth" && name != "order" && name != "amplitude" && name != "phase" &&
            name != "phase_deg")
            throw std::runtime_error(fmt::format("{}: unknown column '{}'; expected: {}", path, name, help));
    const bool depth = t.column.count("depth") > 0, degrees = t.column.count("phase_deg") > 0;
    std::vector<FourierTerm> terms;
    for (std::size_t r = 0; r < t.rows.size(); ++r) {
        const auto& row = t.rows[r];
        FourierTerm term;
        term.z = depth ? -get(t, row, "depth") : get(t, row, "z");
        const double order = get(t, row, "order");
        if (order != std::floor(order) || std::abs(order) > 1e6)
            throw std::runtime_error(
                fmt::format("{}:{}: expected an integer order, got {:g}", path, t.lines[r], order));
        term.order = int(order);
        term.amplitude = get(t, row, "amplitude");
        term.phase = degrees ? get(t, row, "phase_deg") * kPi / 180.0 : get(t, row, "phase");
        terms.push_back(term);
    }
    if (const auto problem = checkFourierTerms(terms, bore))
        throw std::runtime_error(fmt::format("{}:{}: {}{}", path, t.lines[problem->index], problem->message,
                                             problem->first != problem->index
                                                 ? fmt::format(" (first on line {})", t.lines[problem->first])
                                                 : std::string()));
    sortFourierTerms(terms);
    return terms;
}

namespace {
/// The distinct positions of sorted terms and, per position, its terms [first, last).
std::vector<std::pair<std::size_t, std::size_t>> levels(const std::vector<FourierTerm>& terms) {
    std::vector<std::pair<std::size_t, std::size_t>> out;
    for (std::size_t i = 0; i < terms.size();) {
        std::size_t j = i;
        while (j < terms.size() && terms[j].z == terms[i].z) ++j;
        out.emplace_back(i, j);
        i = j;
    }
    return out;
}

double levelValue(const std::vector<FourierTerm>& terms, std::pair<std::size_t, std::size_t> level, double theta) {
    double v = 0.0;
    for (std::size_t i = level.first; i < level.second; ++i)
        v += terms[i].amplitude * std::cos(terms[i].order * (theta - terms[i].phase));
    return v;
}
}  // namespace

double fourierDistortion(const std::vector<FourierTerm>& terms, double z, double theta) {
    const auto lv = levels(terms);
    if (lv.empty()) return 0.0;
    const auto zOf = [&](std::size_t k) { return terms[lv[k].first].z; };
    if (lv.size() == 1 || z <= zOf(0)) return levelValue(terms, lv.front(), theta);
    if (z >= zOf(lv.size() - 1)) return levelValue(terms, lv.back(), theta);
    std::size_t k = 0;
    while (zOf(k + 1) < z) ++k;
    const double t = (z - zOf(k)) / (zOf(k + 1) - zOf(k));
    return (1.0 - t) * levelValue(terms, lv[k], theta) + t * levelValue(terms, lv[k + 1], theta);
}

LinerFieldTable fourierDistortionTable(const std::vector<FourierTerm>& terms, const lube::FilmGrid& grid,
                                       std::string name) {
    std::vector<FourierTerm> sorted = terms;
    sortFourierTerms(sorted);
    const auto lv = levels(sorted);
    std::vector<double> z;
    Eigen::MatrixXd values(Eigen::Index(lv.size()), grid.nTheta());
    for (std::size_t k = 0; k < lv.size(); ++k) {
        z.push_back(sorted[lv[k].first].z);
        for (int j = 0; j < grid.nTheta(); ++j) values(Eigen::Index(k), j) = levelValue(sorted, lv[k], grid.theta(j));
    }
    return LinerFieldTable(std::move(z), std::move(values), std::move(name));
}

// ---- nodal FE result ----------------------------------------------------------------------

namespace {

/// The nodes of a .vtu result: the point-data array `field` is u (3 components) or u_r (1).
std::vector<BoreNode> readVtuNodes(const std::string& path, const std::string& field) {
    const VtuPointField f = readVtuPointField(path, field);
    if (f.values.rows() != 3 && f.values.rows() != 1)
        throw std::runtime_error(fmt::format("{}: point-data array '{}' has {} components; expected 3 (u_x, u_y, u_z) "
                                             "or 1 (u_r)",
                                             path, field, f.values.rows()));
    std::vector<BoreNode> all(std::size_t(f.points.cols()));
    for (Eigen::Index j = 0; j < f.points.cols(); ++j) {
        BoreNode& n = all[std::size_t(j)];
        n.x = f.points(0, j), n.y = f.points(1, j), n.z = f.points(2, j);
        const double r = std::hypot(n.x, n.y);
        if (f.values.rows() == 1)
            n.ur = f.values(0, j);
        else if (r > 0.0)
            n.ur = (f.values(0, j) * n.x + f.values(1, j) * n.y) / r;  // u · (cos θ, sin θ, 0)
    }
    return all;
}

/// The nodes of a CSV result (header: x, y, z and ux, uy, uz or ur).
std::vector<BoreNode> readCsvNodes(const std::string& path) {
    const std::string help = "x, y, z (m, liner frame) and ux, uy, uz or ur (m)";
    std::ifstream probe(path);
    if (!probe) throw std::runtime_error(path + ": no such file or not readable");
    // Which displacement columns: decided from the header (ur, or the three components).
    bool radial = false;
    {
        DataLines lines(probe);
        if (lines.next())
            for (const auto f : splitFields(lines.text())) radial = radial || lower(f) == "ur";
    }
    const Table t = radial ? readTable(path, help, {{"x"}, {"y"}, {"z"}, {"ur"}})
                           : readTable(path, help, {{"x"}, {"y"}, {"z"}, {"ux"}, {"uy"}, {"uz"}});
    if (radial && (t.column.count("ux") || t.column.count("uy")))
        throw std::runtime_error(path + ": give either ur or ux, uy, uz, not both");
    std::vector<BoreNode> all;
    all.reserve(t.rows.size());
    for (const auto& row : t.rows) {
        BoreNode n{get(t, row, "x"), get(t, row, "y"), get(t, row, "z"), 0.0};
        const double r = std::hypot(n.x, n.y);
        if (radial) {
            n.ur = get(t, row, "ur");
        } else if (r > 0.0) {
            n.ur = (get(t, row, "ux") * n.x + get(t, row, "uy") * n.y) / r;  // u · (cos θ, sin θ, 0)
        }
        all.push_back(n);
    }
    return all;
}

}  // namespace

bool isVtuFile(const std::string& path) {
    const std::string ext = lower(std::filesystem::path(path).extension().string());
    return ext == ".vtu";
}

std::vector<BoreNode> readBoreNodes(const std::string& path, double bore, const std::string& field) {
    const std::vector<BoreNode> all = isVtuFile(path) ? readVtuNodes(path, field) : readCsvNodes(path);
    double rMin = std::numeric_limits<double>::infinity(), rMax = 0.0;
    for (const BoreNode& n : all) {
        rMin = std::min(rMin, std::hypot(n.x, n.y));
        rMax = std::max(rMax, std::hypot(n.x, n.y));
    }
    const double R = 0.5 * bore;
    if (std::abs(rMin - R) > 0.01 * R)
        throw std::runtime_error(
            fmt::format("{}: the innermost nodes lie at r = {:g} m (outermost {:g} m), but the bore radius is {:g} m "
                        "(engine.bore/2): the coordinates must be in m, in the liner frame (cylinder axis = z)",
                        path, rMin, rMax, R));
    std::vector<BoreNode> bore_;
    for (const BoreNode& n : all) {
        if (std::hypot(n.x, n.y) > rMin + 1e-3 * R) continue;
        if (std::abs(n.ur) > 0.01 * bore)
            throw std::runtime_error(
                fmt::format("{}: a radial displacement of {:g} m at ({:g}, {:g}, {:g}) m is above "
                            "1% of the bore: check the units (m)",
                            path, n.ur, n.x, n.y, n.z));
        bore_.push_back(n);
    }
    if (bore_.size() < 24)
        throw std::runtime_error(fmt::format("{}: only {} nodes on the bore (r ≤ {:g} m); at least 24 are needed", path,
                                             bore_.size(), rMin + 1e-3 * R));
    return bore_;
}

namespace {

// The bore nodes in the parameter plane (z, s = R θ), θ in [0, 2π), binned in axial strips of the
// typical node spacing and sorted by s within each strip: the k nearest nodes of a point.
class BoreNodeIndex {
public:
    BoreNodeIndex(const std::vector<BoreNode>& nodes, double R, double zLo, double zHi)
        : period_(2.0 * kPi * R), zLo_(zLo), zHi_(zHi),
          spacing_(std::sqrt((zHi - zLo + 1e-9) * period_ / double(nodes.size()))),
          strips_(std::max(1, int((zHi - zLo) / spacing_) + 1)), z_(nodes.size()), s_(nodes.size()),
          u_(nodes.size()), stripStart_(std::size_t(strips_) + 1, 0) {
        std::vector<std::size_t> order(nodes.size());
        std::vector<std::pair<int, double>> key(nodes.size());
        for (std::size_t i = 0; i < nodes.size(); ++i) {
            double th = std::atan2(nodes[i].y, nodes[i].x);
            if (th < 0.0) th += 2.0 * kPi;
            key[i] = {strip(nodes[i].z), std::min(R * th, std::nextafter(period_, 0.0))};
            order[i] = i;
        }
        std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return key[a] < key[b]; });
        for (std::size_t r = 0; r < order.size(); ++r) {
            const std::size_t i = order[r];
            z_[r] = nodes[i].z;
            s_[r] = key[i].second;
            u_[r] = nodes[i].ur;
            ++stripStart_[std::size_t(key[i].first) + 1];
        }
        for (int b = 0; b < strips_; ++b) stripStart_[std::size_t(b) + 1] += stripStart_[std::size_t(b)];
    }

    double period() const { return period_; }
    double z(std::size_t i) const { return z_[i]; }
    double s(std::size_t i) const { return s_[i]; }
    double u(std::size_t i) const { return u_[i]; }

    // The k nearest nodes of (zt, st) into cand (distance, node): every node within w of the
    // target lies in the box |dz|, |ds| ≤ w; w grows until the k-th nearest candidate lies within w.
    void nearest(double zt, double st, int k, std::vector<std::pair<double, std::size_t>>& cand) const {
        for (double w = 2.8 * spacing_;; w *= 1.5) {
            cand.clear();
            const int b0 = strip(zt - w), b1 = strip(zt + w);
            for (int b = b0; b <= b1; ++b) {
                if (2.0 * w >= period_) {
                    gather(b, 0.0, period_, zt, st, cand);
                } else {
                    const double a = std::fmod(st - w + period_, period_), c = a + 2.0 * w;
                    if (c < period_) {
                        gather(b, a, c, zt, st, cand);
                    } else {
                        gather(b, a, period_, zt, st, cand);
                        gather(b, 0.0, c - period_, zt, st, cand);
                    }
                }
            }
            const bool all = (zt - w <= zLo_ && zt + w >= zHi_ && 2.0 * w >= period_);
            if (int(cand.size()) >= k) {
                std::nth_element(cand.begin(), cand.begin() + (k - 1), cand.end());
                if (cand[std::size_t(k) - 1].first <= w || all) break;
            } else if (all) {
                break;
            }
        }
        cand.resize(std::min<std::size_t>(cand.size(), std::size_t(k)));
    }

private:
    int strip(double zz) const { return std::clamp(int((zz - zLo_) / spacing_), 0, strips_ - 1); }
    // Candidates of strip b with s in [a, c] (a, c within [0, period)).
    void gather(int b, double a, double c, double zt, double st, std::vector<std::pair<double, std::size_t>>& cand) const {
        const auto first = s_.begin() + std::ptrdiff_t(stripStart_[std::size_t(b)]);
        const auto last = s_.begin() + std::ptrdiff_t(stripStart_[std::size_t(b) + 1]);
        for (auto it = std::lower_bound(first, last, a); it != last && *it <= c; ++it) {
            const std::size_t i = std::size_t(it - s_.begin());
            const double dz = z_[i] - zt, ds = std::remainder(s_[i] - st, period_);
            cand.emplace_back(std::sqrt(dz * dz + ds * ds), i);
        }
    }

    double period_, zLo_, zHi_, spacing_;
    int strips_;
    std::vector<double> z_, s_, u_;
    std::vector<std::size_t> stripStart_;
};

// The value at (zt, st) of the weighted least-squares quadratic in (dz, ds)/ρ through the
// candidates, ρ just beyond the farthest; Wendland C² weight (1 − d)⁴ (4d + 1).
double movingLeastSquares(const BoreNodeIndex& index, const std::vector<std::pair<double, std::size_t>>& cand,
                          double zt, double st, Eigen::Matrix<double, Eigen::Dynamic, 6>& P, Eigen::VectorXd& rhs) {
    const double rho = std::max_element(cand.begin(), cand.end())->first * (1.0 + 1e-9) + 1e-300;
    P.resize(Eigen::Index(cand.size()), 6);
    rhs.resize(Eigen::Index(cand.size()));
    for (std::size_t c = 0; c < cand.size(); ++c) {
        const std::size_t i = cand[c].second;
        const double a = (index.z(i) - zt) / rho, b = std::remainder(index.s(i) - st, index.period()) / rho;
        const double d = cand[c].first / rho;
        const double wgt = std::sqrt(std::pow(1.0 - d, 4) * (4.0 * d + 1.0));
        P.row(Eigen::Index(c)) << wgt, wgt * a, wgt * b, wgt * a * a, wgt * a * b, wgt * b * b;
        rhs[Eigen::Index(c)] = wgt * index.u(i);
    }
    const Eigen::Matrix<double, 6, 1> coef = P.colPivHouseholderQr().solve(rhs);
    return coef[0];
}

}  // namespace

LinerFieldTable nodalDistortionTable(const std::vector<BoreNode>& nodes, const lube::FilmGrid& grid, double zMin,
                                     double zMax, std::string name) {
    constexpr int kNearest = 24;
    const double R = grid.radius();
    if (int(nodes.size()) < kNearest)
        throw std::runtime_error(
            fmt::format("{}: at least {} bore nodes are needed, got {}", name, kNearest, nodes.size()));
    double zLo = std::numeric_limits<double>::infinity(), zHi = -zLo;
    for (const BoreNode& b : nodes) zLo = std::min(zLo, b.z), zHi = std::max(zHi, b.z);
    const double tol = 1e-6;
    if (zMin < zLo - tol || zMax > zHi + tol)
        throw std::runtime_error(
            fmt::format("{}: the bore nodes cover liner-frame z = {:g} … {:g} m, but the skirt "
                        "sweeps {:g} … {:g} m between TDC and BDC",
                        name, zLo, zHi, zMin, zMax));
    const BoreNodeIndex index(nodes, R, zLo, zHi);
    // Liner-fixed rows.
    const double dzGrid = grid.nAxial() > 1 ? grid.length() / (grid.nAxial() - 1) : 1e-3;
    const double hMax = std::min(0.5 * dzGrid, 0.5e-3);
    const int rows = std::max(2, int(std::ceil((zMax - zMin) / hMax)) + 1);
    std::vector<double> zr(std::size_t(rows), zMin);
    for (int k = 0; k < rows; ++k) zr[std::size_t(k)] = zMin + (zMax - zMin) * k / (rows - 1);
    if (!(zMax > zMin)) zr.resize(1);
    Eigen::MatrixXd values(Eigen::Index(zr.size()), grid.nTheta());
    std::vector<std::pair<double, std::size_t>> cand;
    Eigen::Matrix<double, Eigen::Dynamic, 6> P;
    Eigen::VectorXd rhs;
    for (std::size_t k = 0; k < zr.size(); ++k)
        for (int j = 0; j < grid.nTheta(); ++j) {
            const double zt = zr[k], st = R * grid.theta(j);
            index.nearest(zt, st, kNearest, cand);
            values(Eigen::Index(k), j) = movingLeastSquares(index, cand, zt, st, P, rhs);
        }
    return LinerFieldTable(std::move(zr), std::move(values), std::move(name));
}

}  // namespace flexehd::cosim
