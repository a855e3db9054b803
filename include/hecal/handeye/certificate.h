// A certificate of global optimality for a hand–eye answer (docs/certificate.md).
//
// Problem. Every pose-based calibration solves Z = A_i X B_i (problem.h). Its chordal weighted
// least squares
//     minimise  Σ_i w_r ‖R_Ai R_X R_Bi − R_Z‖²_F + w_t ‖R_Ai (R_X t_Bi + t_X) + t_Ai − t_Z‖²
//     over R_X, R_Z ∈ SO(3), t_X, t_Z ∈ R³
// is a quadratically constrained quadratic program in z = (vec R_X, vec R_Z, t_X, t_Z, y),
// y² = 1 homogenising the linear terms: cost zᵀ Q z, the translations eliminated in closed form
// (Schur complement), leaving r = (vec R_X, vec R_Z, y) and Q_r (19 × 19). Its Lagrangian dual is
// tight in practice (Giamou, Ma, Peretroukhin and Kelly, "Certifiably globally optimal extrinsic
// calibration from per-sensor egomotion", RA-L 4(2), 2019; Wise, Giamou, Khoubyarian, Grover and
// Kelly, "Certifiably optimal monocular hand-eye calibration", MFI 2020, for AX = XB with an
// unknown scale; Horn et al., RA-L 2021, for AX = ZB with dual quaternions).
//
// Certificate (Rosen et al., SE-Sync, IJRR 2019, §4; Briales and Gonzalez-Jimenez, CVPR 2017):
// with the constraints c_jᵀ c_k = δ_jk y² on the columns of each rotation (RᵀR = I) and y² = 1,
// a point r̂ is a global minimum when multipliers Λ_X, Λ_Z (symmetric 3 × 3) and ρ exist with
//     H = Q_r − blkdiag(Λ_X ⊗ I₃, Λ_Z ⊗ I₃, −tr Λ_X − tr Λ_Z) − ρ e_y e_yᵀ,
//     H r̂ = 0  (stationarity)   and   H ⪰ 0,
// both to a relative tolerance of λ_max(Q_r) (below).
// Then every feasible r has cost rᵀ Q_r r = rᵀ H r + ρ ≥ ρ = r̂ᵀ Q_r r̂: ρ is a lower bound on the
// global minimum (weak duality) and the dual gap r̂ᵀ Q_r r̂ − ρ is zero. The stationarity
// equations are linear in (Λ_X, Λ_Z, ρ): 19 equations, 13 unknowns, solved by least squares (a
// regular point, so at a local minimum they are consistent and the multipliers unique); H ⪰ 0 is
// one 19 × 19 eigen-decomposition. No semidefinite solver: microseconds.
// Over O(3) (no handedness constraint) this certifies a global minimum over O(3) × O(3) ⊃
// SO(3) × SO(3), which is stronger. When it fails the point is either a local minimum or one
// this relaxation cannot certify (its dual is not tight there); the caller tries other starts.
//
// Which point. hecal's answers minimise other costs (ml's whitened Lie-algebra residuals, a
// closed form's own), so the certificate is for the chordal problem's local minimum reached
// from the answer (Gauss–Newton on SO(3) × SO(3), `polished`), and says how far the answer is
// from it. Weights: w_r = 1/σ_r², w_t = 1/σ_t² from the noise of the calibration (robot and
// camera combined, the rotation noise's lever arm L = LengthScale included in σ_t).
#pragma once

#include "hecal/geometry/types.h"
#include "hecal/handeye/problem.h"

namespace hecal::handeye {

struct ChordalWeights {
  double rotation = 1.0;     // w_r, 1/rad²
  double translation = 1.0;  // w_t, 1/m²
};

struct Certificate {
  bool certified = false;
  Solution polished;            // the chordal problem's local minimum reached from the answer
  double cost = 0.0;            // r̂ᵀ Q_r r̂ at `polished`
  double lower_bound = 0.0;     // ρ: no feasible (X, Z) has a lower cost (when certified)
  double gap = 0.0;             // cost − lower_bound (≥ 0 up to rounding)
  double min_eigenvalue = 0.0;  // of H, relative to the largest eigenvalue of Q_r
  double stationarity = 0.0;    // |H r̂| / (λ_max(Q_r) |r̂|): how well H r̂ = 0 is solved
  // The answer's distance from `polished`: rotation (rad, the larger of X's and Z's) and
  // translation (m, the larger).
  double distance_rotation = 0.0;
  double distance_translation = 0.0;
};

// Relative tolerances of the test above: H's smallest eigenvalue ≥ −kCertificateEigenTolerance
// · λ_max(Q_r) and the stationarity residual ≤ kCertificateStationarityTolerance.
inline constexpr double kCertificateEigenTolerance = 1e-9;
inline constexpr double kCertificateStationarityTolerance = 1e-9;

// The weights above from per-component sigmas of the combined robot and camera noise.
ChordalWeights WeightsFromSigmas(double rotation_sigma, double translation_sigma,
                                 double length_scale);

// Polishes `answer` to the chordal problem's local minimum and certifies it. Requires at least
// two stations.
Certificate CertifyGlobalOptimum(const Problem& problem, const Solution& answer,
                                 const ChordalWeights& weights);

}  // namespace hecal::handeye
