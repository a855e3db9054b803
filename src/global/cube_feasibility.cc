#include "hecal/global/cube_feasibility.h"

#include <glpk.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "hecal/geometry/so3.h"

namespace hecal::global {
namespace {

struct Row {
  Eigen::Vector3d coefficients;  // of t
  double upper = 0.0;
};

// Unit normals q with q·x ≤ 0 on C(a, rho_a) and C(c, rho_c) (unit a, c): the two bitangent
// planes and the far-side tangent plane of each cap. Empty when the caps are not separable.
std::vector<Eigen::Vector3d> SupportingNormals(const Eigen::Vector3d& a, double rho_a,
                                               const Eigen::Vector3d& c, double rho_c) {
  std::vector<Eigen::Vector3d> normals;
  const double cos_theta = a.dot(c);
  const Eigen::Vector3d cross = a.cross(c);
  if (cross.norm() < 1e-12 || rho_a >= M_PI / 2 || rho_c >= M_PI / 2) return normals;
  const Eigen::Vector3d n = cross.normalized();
  // In-plane part α a + β c with q·a = −sin ρ_a, q·c = −sin ρ_c (Gram system).
  const double sa = std::sin(rho_a), sc = std::sin(rho_c);
  const double det = 1.0 - cos_theta * cos_theta;
  const double alpha = (-sa + cos_theta * sc) / det;
  const double beta = (-sc + cos_theta * sa) / det;
  const Eigen::Vector3d in_plane = alpha * a + beta * c;
  const double squared = in_plane.squaredNorm();
  if (squared >= 1.0) return normals;  // the caps reach each other round the back
  const double z = std::sqrt(1.0 - squared);
  normals.push_back(in_plane + z * n);
  normals.push_back(in_plane - z * n);
  auto far_side = [&](const Eigen::Vector3d& x, double rho_x, const Eigen::Vector3d& y,
                      double rho_y) {
    const Eigen::Vector3d away = -(y - y.dot(x) * x).normalized();
    const Eigen::Vector3d q = std::cos(rho_x) * away - std::sin(rho_x) * x;
    if (q.dot(y) <= -std::sin(rho_y)) normals.push_back(q);
  };
  far_side(a, rho_a, c, rho_c);
  far_side(c, rho_c, a, rho_a);
  return normals;
}

std::vector<Row> Rows(const EpipolarProblem& problem, const CubeQuery& query) {
  const double widened = query.epsilon + std::sqrt(3.0) * query.half_width;  // ε + δ
  const Eigen::Matrix3d R = so3::Exp(query.centre);
  std::vector<Row> rows;
  for (const EpipolarMotion& motion : problem.motions) {
    const Eigen::Matrix3d R_B = motion.hand.linear();
    const Eigen::Vector3d& t_B = motion.hand.translation();
    const Eigen::Matrix3d M = R_B - Eigen::Matrix3d::Identity();
    for (const BearingPair& pair : motion.pairs) {
      const Eigen::Vector3d a = (R * pair.first).normalized();
      const Eigen::Vector3d c = -(R_B * R * pair.second).normalized();
      for (const Eigen::Vector3d& q : SupportingNormals(a, widened, c, widened)) {
        rows.push_back({M.transpose() * q, -q.dot(t_B)});
      }
    }
  }
  return rows;
}

// GLPK on the rows `active`: the LP's point t, or nullopt when infeasible (proved by the solver;
// a failure of the solver returns the hint, which keeps the cube).
std::optional<Eigen::Vector3d> SolveSubset(const std::vector<Row>& rows,
                                           const std::vector<int>& active, double bound,
                                           const Eigen::Vector3d& hint) {
  glp_prob* lp = glp_create_prob();
  glp_set_obj_dir(lp, GLP_MIN);
  glp_add_cols(lp, 3);
  for (int j = 1; j <= 3; ++j) glp_set_col_bnds(lp, j, GLP_DB, -bound, bound);
  glp_add_rows(lp, int(active.size()));
  std::vector<int> ia(1), ja(1);
  std::vector<double> ar(1);
  for (std::size_t i = 0; i < active.size(); ++i) {
    const Row& row = rows[active[i]];
    glp_set_row_bnds(lp, int(i) + 1, GLP_UP, 0.0, row.upper);
    for (int j = 0; j < 3; ++j) {
      ia.push_back(int(i) + 1);
      ja.push_back(j + 1);
      ar.push_back(row.coefficients[j]);
    }
  }
  glp_load_matrix(lp, int(ia.size()) - 1, ia.data(), ja.data(), ar.data());
  glp_smcp parameters;
  glp_init_smcp(&parameters);
  parameters.msg_lev = GLP_MSG_OFF;
  parameters.presolve = GLP_ON;
  const int code = glp_simplex(lp, &parameters);
  const int status = code == 0 ? glp_get_status(lp) : GLP_UNDEF;
  std::optional<Eigen::Vector3d> result = hint;
  if (code == GLP_ENOPFS || status == GLP_NOFEAS) {
    result = std::nullopt;
  } else if (status == GLP_OPT || status == GLP_FEAS) {
    result =
        Eigen::Vector3d(glp_get_col_prim(lp, 1), glp_get_col_prim(lp, 2), glp_get_col_prim(lp, 3));
  }
  glp_delete_prob(lp);
  return result;
}

}  // namespace

std::optional<Eigen::Vector3d> TestCube(const EpipolarProblem& problem, const CubeQuery& query,
                                        const Eigen::Vector3d& hint, int* lps) {
  const std::vector<Row> rows = Rows(problem, query);
  // Cutting planes: solve on the most violated rows, add the rows the point violates, repeat.
  // An infeasible subset proves the whole programme infeasible.
  constexpr double kTolerance = 1e-10;  // metres
  constexpr int kRowsPerRound = 24;
  std::vector<char> in(rows.size(), 0);
  std::vector<int> active;
  Eigen::Vector3d t = hint.cwiseMax(-query.translation_bound).cwiseMin(query.translation_bound);
  while (true) {
    std::vector<std::pair<double, int>> violated;
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const double excess = rows[i].coefficients.dot(t) - rows[i].upper;
      if (excess > kTolerance && !in[i]) violated.emplace_back(-excess, int(i));
    }
    if (violated.empty()) return t;
    const int take = std::min<int>(kRowsPerRound, int(violated.size()));
    std::partial_sort(violated.begin(), violated.begin() + take, violated.end());
    for (int k = 0; k < take; ++k) {
      active.push_back(violated[k].second);
      in[violated[k].second] = 1;
    }
    if (lps) ++*lps;
    const auto next = SolveSubset(rows, active, query.translation_bound, t);
    if (!next) return std::nullopt;
    if (*next == t) return t;  // the solver gave no answer: keep the cube
    t = *next;
  }
}

}  // namespace hecal::global
