/* jointplay's compiled integration loop: a whole run, events included, in one call.
 *
 * Method: variable-order (1-5), quasi-constant step size BDF in the NDF form of Shampine and
 * Reichelt ("The MATLAB ODE Suite", SIAM J. Sci. Comput. 18, 1997), with backward differences
 * kept as an array D and rescaled when the step changes. Simplified Newton on I - c J, the
 * Jacobian refreshed only when Newton fails to converge with a stale one, the LU refreshed when
 * c changes. Dense output is the interpolating polynomial of the differences.
 *
 * The model is CasADi-generated C in another shared library; its functions are called through
 * pointers with CasADi's calling convention (arg, res, iw, w, mem). Drive torques are a small
 * postfix program per driven joint (or a piecewise-linear table), so a scene's torques need no
 * compiler. Quadratures (drive work, and per clearance joint the normal impulse, the energy
 * taken out by damping and by friction) ride in the same difference array, outside Newton and
 * outside the error test, like CVODES's quadratures with errconQ off.
 *
 * Events, per clearance joint, checked on the dense output at the end and at interior points of
 * every accepted step:
 * - onset (penetration delta crosses 0 upwards while the joint is free): the crossing is located
 *   on the dense output to round-off, the step is redone to land exactly there (the model's
 *   damping after the onset depends on the approach speed captured at it), and the approach
 *   speed d(delta)/dt is captured;
 * - separation (delta crosses 0 downwards while in contact): located, recorded;
 * - maximum penetration (d(delta)/dt crosses 0 downwards in contact), located, and peak
 *   normal force: the normal forces are sampled with the penetrations (the model's
 *   normal_force, the contact law's f_n alone, where it has one; the step's ends come from the
 *   quadrature rates and the step before), and a sampled maximum that can beat the phase's
 *   peak so far is located by Brent's method on the dense output; recorded per phase.
 * The state is scaled: eccentricities in units of their joint's clearance, so one absolute
 * tolerance means the same for angles and micrometre play.
 *
 * Forward sensitivities (only when a run asks for them): d state / d parameter integrated
 * beside the state by the staggered direct method and carried through every onset (see
 * "forward sensitivities" below).
 *
 * Wear (only for a model with a generated `wear` function): Archard's volume rate and its
 * spread over the bearing's and the journal's surfaces are integrated over every step that
 * stands, by Gauss-Legendre quadrature on the dense output in time and exactly over each
 * angular bin (see wear_step).
 */
#include <math.h>
#include <signal.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

typedef long long jp_int; /* casadi_int of the generated code (checked from Python) */
typedef int (*casadi_eval)(const double **arg, double **res, jp_int *iw, double *w, int mem);

enum { MAX_ORDER = 5, NEWTON_MAXITER = 4, INTERIOR = 3 };
/* Stability guard (see bdf_adapt): every STABILITY_WINDOW accepted steps, a share of error-test
 * failures of at least 1 / STABILITY_FAILURE_SHARE at order >= 3 caps the order at
 * STABILITY_ORDER for the next STABILITY_HOLD steps. */
enum { STABILITY_WINDOW = 20, STABILITY_FAILURE_SHARE = 5, STABILITY_ORDER = 2,
       STABILITY_HOLD = 50 };
enum {
  JP_OK = 0, JP_TOO_MUCH_WORK = 1, JP_STEP_COLLAPSED = 2, JP_NONFINITE = 3,
  JP_INTERRUPTED = 4, JP_BAD_TORQUE = 5, JP_CHATTER = 6, JP_NO_MEMORY = 7
};

/* Torque program opcodes. */
enum {
  OP_CONST = 0, OP_TIME = 1, OP_NEG = 2, OP_ADD = 3, OP_SUB = 4, OP_MUL = 5, OP_DIV = 6,
  OP_POW = 7, OP_SIN = 8, OP_COS = 9, OP_TAN = 10, OP_EXP = 11, OP_LOG = 12, OP_SQRT = 13,
  OP_ABS = 14, OP_TANH = 15, OP_SINH = 16, OP_COSH = 17, OP_ATAN = 18, OP_MIN = 19,
  OP_MAX = 20, OP_STEP = 21, OP_LE = 22, OP_LT = 23, OP_IF_ELSE_ZERO = 24, OP_SQ = 25,
  OP_INV = 26, OP_TWICE = 27
};
#define STACK_DEPTH 256

/* Which Newton matrix a second-order system's step factors (jp_sim.newton). From this many
 * coordinates on, the n x n reduction by default: below it the full 2n x 2n LU has at most
 * 22 rows and costs little beside the Jacobian, and the built-in scenes' published runs
 * (8 coordinates) were measured through it. The two are equal up to round-off, which the
 * paper scene's chaotic impact burst amplifies into a different step sequence (README,
 * "Work-precision"). */
#define JP_REDUCED_NEWTON_FROM 12
enum { JP_NEWTON_AUTO = 0, JP_NEWTON_FULL = 1, JP_NEWTON_REDUCED = 2 };

typedef struct {
  casadi_eval eval;
  jp_int n_in, n_out, sz_arg, sz_res, sz_iw, sz_w;
  const jp_int *sparsity_out0; /* CCS pattern of output 0 (for the Jacobian) */
} jp_function;

/* Everything a run needs, filled from Python (mirrored by a ctypes Structure). */
typedef struct {
  int nq, nx, nc, ntau, np;
  const double *p;          /* np parameters */
  const double *scale;      /* nx: state = scale * z */
  const int *ecc_index;     /* 2 nc: coordinate index of ex_j, ey_j */
  const double *clearance;  /* nc */
  const int *drive_index;   /* ntau: coordinate index of each driven angle */
  /* torques: per driven joint a program [start, start+len) in ops/consts, or a table */
  const int *torque_kind;   /* ntau: 0 program, 1 table */
  const int *torque_start, *torque_len;
  const int *ops;
  const double *consts;
  const double *table_t, *table_v; /* tables: [start, start+len) */
  double rtol, atol, h_max, h_init;
  long max_steps;           /* steps allowed between two outputs */
  long max_events;          /* event locations allowed between two outputs */
  int max_order;            /* highest BDF order used (1..5) */
  jp_function f, jac, contact;
  jp_function wear;         /* eval NULL: no wear integrated */
  int wear_bins;            /* angular bins around each surface */
  jp_function normal;       /* contact's f_n alone; eval NULL: taken from contact */
  /* Forward sensitivities (see sens_step): ns named parameters, each a direction in the
   * parameter vector (dp, ns x np), its clearance change (dc, ns x nc) and the initial
   * state's derivative (s0, ns x nx, unscaled); jac_in is the model's
   * jac_forward_dynamics_inputs, sp_p and sp_v the CCS patterns of its p and v_imp blocks. */
  int ns;
  const double *dp, *dc, *s0;
  jp_function jac_in;
  const jp_int *sp_p, *sp_v;
  /* Sensitivities in the error test too (CVODES's errconS): each block's norm, with weights
   * atol / sens_scale + rtol |Z| (sens_scale: the parameter's size, so that S sens_scale is
   * the state's change for a 100 % change of it), beside the state's; else (0) outside it,
   * and the state's steps are those of a run without sensitivities. */
  int sens_errcon;
  const double *sens_scale;
  /* The model's forward_dynamics_input_directions (eval NULL: not generated; jac_in's blocks
   * are read instead): d xdot along dir_k seed columns in (p, v_imp) at a time, dense. */
  jp_function dir_in;
  int dir_k;
  /* Mechanisms, whose cut clearance joints have no eccentricity coordinates: gap_fn(x, p) ->
   * (delta, rate, ex, ey), nc each, read instead of ecc_index; power_fn(x, tau, p, v_imp) ->
   * the driver's power, integrated instead of sum tau_k qdot[drive_index[k]]. eval NULL (the
   * serial arms): not used. */
  jp_function gap_fn, power_fn;
  /* Whether the event scan locates each phase's peak normal force (and, with sensitivities,
   * its derivatives). 0: the force is neither sampled nor refined, the peak columns stay NaN;
   * nothing else changes (the force feeds no step, event or quadrature), so the trajectory is
   * the same to the bit. A calibration's trial runs, which read only the motion, skip it. */
  int peaks;
  /* Which Newton matrix a second-order system's steps factor: JP_NEWTON_AUTO, _FULL or
   * _REDUCED (the environment variable JOINTPLAY_NEWTON, where set, overrides it). */
  int newton;
} jp_config;

/* One contact phase: see jointplay.results.Impacts. */
enum {
  PH_JOINT, PH_T_ON, PH_V_ON, PH_EX, PH_EY, PH_F_PEAK, PH_T_F, PH_D_MAX, PH_T_D,
  PH_T_OFF, PH_V_OFF, PH_IMPULSE, PH_DAMPING, PH_FRICTION, PH_FIELDS
};

typedef struct {
  jp_config c;
  int N;           /* nx + quadratures */
  int nquad;
  /* integrator state */
  double t, h, h_abs;
  int order, n_equal_steps, have_lu, current_jac, started;
  double *D;       /* (MAX_ORDER + 3) x N, row k = k-th difference */
  double *D_save;
  double *J, *LU; int *piv;
  double *LT, *JqT;  /* L's columns (lu_lower_columns); Jq's columns (reduced Newton matrix) */
  /* Newton matrix I - c J of a second-order system, J = [0 D; Jq Jv] (scaled; D diagonal):
   * with du solved from the n x n K = I - c Jv - c^2 Jq D, dq = r_q + c D du (exact; an LU
   * of n instead of 2n rows, 8x fewer operations). reduced: J had that form at its last
   * evaluation; lu_c: the c the LU was formed with. newton: which factorisation is allowed,
   * the config's, or set from the environment variable JOINTPLAY_NEWTON at each reset
   * ("full", "reduced"; "auto": reduced from JP_REDUCED_NEWTON_FROM coordinates on), so that
   * a test can compare the two paths. */
  int reduced, newton; double lu_c; double *rhs_u;
  double *y_pred, *psi, *d, *y_new, *f_buf, *dy, *scal, *err, *work_n;
  double *xs, *xdot;           /* unscaled state and its derivative */
  double *tau, *u_hold;
  double tau_t;                /* the time tau holds the torques of, NAN: none */
  double *tau_scene;           /* the scene's part of tau (without the held torques) */
  int *torque_same;            /* per driven joint: an earlier one with the same torque, or -1 */
  double *v_imp, *flags;       /* per clearance joint */
  double *g_out;               /* gap_fn's outputs: delta, rate, ex, ey (4 nc) */
  int *armed;                  /* penetration has been positive since the onset */
  int *rising;                 /* normal force rising at the end of the last step */
  double *tmp_y, *tmp_y2;
  double *samples;             /* NS x nx: unscaled states at the scan's sample times */
  /* Normal forces the scan need not compute again (see scan_events): fn_quad from the last
   * quadrature rates, at time fn_quad_t; fn_carry, the last standing step's force samples at
   * its end, time fn_carry_t. Each holds for the impact speeds of generation *_gen (v_gen
   * counts the onsets, which change v_imp and with it the force). */
  double *fn_quad, *fn_carry, fn_quad_t, fn_carry_t;
  long fn_quad_gen, fn_carry_gen, v_gen;
  /* CasADi work */
  const double **arg; double **res; jp_int *iw; double *w;
  double *jac_sparse, *c_out; /* contact outputs: 8 x nc */
  /* phases */
  double *phases; long n_phases, cap_phases;
  long *open_phase;            /* per joint: row of the open phase or -1 */
  /* statistics */
  long n_steps, n_rhs, n_jac, n_lu, n_err_fail, n_newton_fail, n_events, n_onsets;
  long n_lu_reduced; /* of n_lu, those of the n x n reduced Newton matrix */
  int order_cap, cap_steps, window_steps, recent_failures; /* stability-limit guard */
  double landing_target; /* the onset time a redone step aims at, else +inf */
  double last_safety, last_err_norm, t_old, h_abs_old; int order_old, n_equal_old;
  /* failure */
  int status; double fail_t; int fail_joint; double fail_h;
  /* wear: outputs of the model's wear function (7 x nc), volume (nc), depth (2 x nc x bins) */
  double *wear_out, *wear_volume, *wear_depth;
  /* sensitivities: columns sens_col.. of D hold ns blocks of nx (scaled, like the state);
   * Js / LUs / LTs / pivs the Jacobian at the step's end and its Newton matrix; bz the
   * scaled forcing (ns x nx); v_sens d v_imp / d parameter (nc x ns); phase_sens one record
   * of sens_record values per phase (see sens_record_size) */
  int sens_col, sens_record;
  double *Js, *LUs, *LTs; int *pivs;
  double *bz, *fp_sparse, *fv_sparse, *v_sens, *sens_tmp, *f_minus, *f_plus;
  double *seeds, *dir_out; /* dir_in's seeds ((np + nc) x dir_k) and output (nx x dir_k) */
  double *phase_sens;
  long n_sens_jac;
} jp_sim;

static volatile sig_atomic_t jp_interrupted = 0;
static void jp_on_sigint(int sig) { (void)sig; jp_interrupted = 1; }

/* ---- small helpers ------------------------------------------------------------------------ */

static double rms(int n, const double *x, const double *scal) {
  double s = 0.0;
  for (int i = 0; i < n; ++i) { double v = x[i] / scal[i]; s += v * v; }
  return sqrt(s / n);
}

static int all_finite(int n, const double *x) {
  for (int i = 0; i < n; ++i) if (!isfinite(x[i])) return 0;
  return 1;
}

static double torque_program(const jp_config *c, int k, double t, int *ok) {
  double stack[STACK_DEPTH]; int sp = 0;
  const int *op = c->ops + c->torque_start[k];
  const double *cs = c->consts + c->torque_start[k];
  for (int i = 0; i < c->torque_len[k]; ++i) {
    switch (op[i]) {
      case OP_CONST: stack[sp++] = cs[i]; break;
      case OP_TIME: stack[sp++] = t; break;
      case OP_NEG: stack[sp - 1] = -stack[sp - 1]; break;
      case OP_ADD: sp--; stack[sp - 1] += stack[sp]; break;
      case OP_SUB: sp--; stack[sp - 1] -= stack[sp]; break;
      case OP_MUL: sp--; stack[sp - 1] *= stack[sp]; break;
      case OP_DIV: sp--; stack[sp - 1] /= stack[sp]; break;
      case OP_POW: sp--; stack[sp - 1] = pow(stack[sp - 1], stack[sp]); break;
      case OP_SIN: stack[sp - 1] = sin(stack[sp - 1]); break;
      case OP_COS: stack[sp - 1] = cos(stack[sp - 1]); break;
      case OP_TAN: stack[sp - 1] = tan(stack[sp - 1]); break;
      case OP_EXP: stack[sp - 1] = exp(stack[sp - 1]); break;
      case OP_LOG: stack[sp - 1] = log(stack[sp - 1]); break;
      case OP_SQRT: stack[sp - 1] = sqrt(stack[sp - 1]); break;
      case OP_ABS: stack[sp - 1] = fabs(stack[sp - 1]); break;
      case OP_TANH: stack[sp - 1] = tanh(stack[sp - 1]); break;
      case OP_SINH: stack[sp - 1] = sinh(stack[sp - 1]); break;
      case OP_COSH: stack[sp - 1] = cosh(stack[sp - 1]); break;
      case OP_ATAN: stack[sp - 1] = atan(stack[sp - 1]); break;
      case OP_MIN: sp--; stack[sp - 1] = fmin(stack[sp - 1], stack[sp]); break;
      case OP_MAX: sp--; stack[sp - 1] = fmax(stack[sp - 1], stack[sp]); break;
      case OP_STEP: stack[sp - 1] = stack[sp - 1] >= 0.0 ? 1.0 : 0.0; break;
      case OP_LE: sp--; stack[sp - 1] = stack[sp - 1] <= stack[sp] ? 1.0 : 0.0; break;
      case OP_LT: sp--; stack[sp - 1] = stack[sp - 1] < stack[sp] ? 1.0 : 0.0; break;
      case OP_IF_ELSE_ZERO: sp--; stack[sp - 1] = stack[sp - 1] != 0.0 ? stack[sp] : 0.0; break;
      case OP_SQ: stack[sp - 1] *= stack[sp - 1]; break;
      case OP_INV: stack[sp - 1] = 1.0 / stack[sp - 1]; break;
      case OP_TWICE: stack[sp - 1] *= 2.0; break;
      default: *ok = 0; return NAN;
    }
  }
  return sp == 1 ? stack[0] : (*ok = 0, NAN);
}

static double torque_table(const jp_config *c, int k, double t) {
  const double *ts = c->table_t + c->torque_start[k];
  const double *vs = c->table_v + c->torque_start[k];
  int n = c->torque_len[k];
  if (t <= ts[0]) return vs[0];
  if (t >= ts[n - 1]) return vs[n - 1];
  int lo = 0, hi = n - 1;
  while (hi - lo > 1) { int mid = (lo + hi) / 2; if (ts[mid] <= t) lo = mid; else hi = mid; }
  double s = (t - ts[lo]) / (ts[hi] - ts[lo]);
  return vs[lo] + s * (vs[hi] - vs[lo]);
}

/* tau = scene torques at t + held torques; 0 if all finite, else 1 + index of the bad one.
 * Newton's iterations, the Jacobian and the quadratures ask for the same t in turn: tau is
 * kept for the last t it was computed at (tau_t; NAN after a hold changes the torques). */
static int torques_at(jp_sim *s, double t) {
  const jp_config *c = &s->c;
  if (t == s->tau_t) return 0;
  s->tau_t = NAN;
  for (int k = 0; k < c->ntau; ++k) {
    int ok = 1, same = s->torque_same[k];
    double v = same >= 0 ? s->tau_scene[same]
               : c->torque_kind[k] == 0 ? torque_program(c, k, t, &ok) : torque_table(c, k, t);
    s->tau_scene[k] = v;
    v += s->u_hold[k];
    if (!ok || !isfinite(v)) return k + 1;
    s->tau[k] = v;
  }
  s->tau_t = t;
  return 0;
}

static int call(jp_sim *s, const jp_function *fn) {
  return fn->eval(s->arg, s->res, s->iw, s->w, 0);
}

/* Unscaled state xs from the scaled one z. */
static void unscale(jp_sim *s, const double *z) {
  for (int i = 0; i < s->c.nx; ++i) s->xs[i] = z[i] * s->c.scale[i];
}

/* dz/dt of the state part (scaled) at (t, z); returns 0 on success. */
static int rhs(jp_sim *s, double t, const double *z, double *dz) {
  const jp_config *c = &s->c;
  int bad = torques_at(s, t);
  if (bad) { s->status = JP_BAD_TORQUE; s->fail_t = t; s->fail_joint = bad - 1; return -1; }
  unscale(s, z);
  s->arg[0] = s->xs; s->arg[1] = s->tau; s->arg[2] = c->p; s->arg[3] = s->v_imp;
  s->res[0] = s->xdot;
  if (call(s, &c->f)) return 1;
  s->n_rhs++;
  for (int i = 0; i < c->nx; ++i) dz[i] = s->xdot[i] / c->scale[i];
  return all_finite(c->nx, dz) ? 0 : 1;
}

/* Contact outputs at unscaled state xs (contact_at: at s->xs): c_out[k * nc + j], k in delta,
 * delta_dot, v_t, f_n, f_t, f_x, f_y, dissipation. */
static void contact_of(jp_sim *s, const double *xs) {
  const jp_config *c = &s->c;
  s->arg[0] = xs; s->arg[1] = c->p; s->arg[2] = s->v_imp;
  for (int k = 0; k < 8; ++k) s->res[k] = s->c_out + k * c->nc;
  call(s, &c->contact);
}
static void contact_at(jp_sim *s) { contact_of(s, s->xs); }

/* The normal forces alone at unscaled state xs, into their place in c_out (the rest of c_out
 * is left as it was when the model has a function for them, else is contact's too). */
static void normal_of(jp_sim *s, const double *xs) {
  const jp_config *c = &s->c;
  if (!c->normal.eval) { contact_of(s, xs); return; }
  s->arg[0] = xs; s->arg[1] = c->p; s->arg[2] = s->v_imp;
  s->res[0] = s->c_out + 3 * c->nc;
  call(s, &c->normal);
}

/* Quadrature integrands at time t and scaled state z (torques already at t): drive power, then
 * per joint normal force, damping power, friction power; all in the order of the quadrature
 * block. The normal forces are kept (fn_quad) for the event scan. */
static void quadrature_rates(jp_sim *s, double t, const double *z, double *g) {
  const jp_config *c = &s->c;
  unscale(s, z);
  double power = 0.0;
  if (c->power_fn.eval) {
    s->arg[0] = s->xs; s->arg[1] = s->tau; s->arg[2] = c->p; s->arg[3] = s->v_imp;
    s->res[0] = &power;
    call(s, &c->power_fn);
  } else {
    for (int k = 0; k < c->ntau; ++k) power += s->tau[k] * s->xs[c->nq + c->drive_index[k]];
  }
  g[0] = power;
  if (c->nc) {
    contact_at(s);
    int nc = c->nc;
    for (int j = 0; j < nc; ++j) {
      double fn = s->c_out[3 * nc + j], ft = s->c_out[4 * nc + j], vt = s->c_out[2 * nc + j];
      double diss = s->c_out[7 * nc + j];
      double friction = -ft * vt;
      g[1 + 3 * j] = fn;
      g[2 + 3 * j] = diss - friction;
      g[3 + 3 * j] = friction;
    }
    memcpy(s->fn_quad, s->c_out + 3 * nc, nc * sizeof(double));
    s->fn_quad_t = t; s->fn_quad_gen = s->v_gen;
  }
}

/* Penetration and its rate of joint j from an unscaled state. */
/* A mechanism's gaps (every joint's, into g_out) from its model at unscaled state xs. */
static void model_gaps(jp_sim *s, const double *xs) {
  const jp_config *c = &s->c;
  s->arg[0] = xs; s->arg[1] = c->p;
  for (int k = 0; k < 4; ++k) s->res[k] = s->g_out + k * c->nc;
  call(s, &c->gap_fn);
}

static void gap(jp_sim *s, const double *xs, int j, double *delta, double *rate) {
  const jp_config *c = &s->c;
  if (c->gap_fn.eval) {
    model_gaps(s, xs);
    *delta = s->g_out[j];
    if (rate) *rate = s->g_out[c->nc + j];
    return;
  }
  int ix = c->ecc_index[2 * j], iy = c->ecc_index[2 * j + 1];
  double ex = xs[ix], ey = xs[iy], vx = xs[c->nq + ix], vy = xs[c->nq + iy];
  double floor = 1e-6 * c->clearance[j];
  double e = sqrt(fmax(ex * ex + ey * ey, floor * floor));
  *delta = e - c->clearance[j];
  if (rate) *rate = (ex * vx + ey * vy) / e;
}

/* ---- dense linear algebra (row-major n x n, partial pivoting) -------------------------------- */

static int lu_factor(int n, double *a, int *piv) {
  for (int k = 0; k < n; ++k) {
    int p = k; double big = fabs(a[k * n + k]);
    for (int i = k + 1; i < n; ++i) if (fabs(a[i * n + k]) > big) { big = fabs(a[i * n + k]); p = i; }
    piv[k] = p;
    if (big == 0.0) return 1;
    if (p != k) for (int j = 0; j < n; ++j) { double tmp = a[k * n + j]; a[k * n + j] = a[p * n + j]; a[p * n + j] = tmp; }
    double inv = 1.0 / a[k * n + k];
    const double *pivot_row = a + k * n;
    for (int i = k + 1; i < n; ++i) {
      double *row = a + i * n;
      double l = row[k] *= inv;
      if (l != 0.0) for (int j = k + 1; j < n; ++j) row[j] -= l * pivot_row[j];
    }
  }
  return 0;
}

/* The columns of L (the part of a below its diagonal) as rows of lt, for lu_solve. */
static void lu_lower_columns(int n, const double *a, double *lt) {
  for (int j = 0; j < n; ++j)
    for (int i = j + 1; i < n; ++i) lt[j * n + i] = a[i * n + j];
}

/* b <- A^-1 b from lu_factor's a and piv, and lt from lu_lower_columns. The forward
 * substitution runs column by column: each b[i] takes its terms in the order of the row-wise
 * dot product (j ascending), so the result is the same to the bit, but the updates of
 * different rows are independent (no chain of dependent additions) and contiguous in lt. */
static void lu_solve(int n, const double *a, const double *lt, const int *piv, double *b) {
  for (int k = 0; k < n; ++k) { int p = piv[k]; if (p != k) { double tmp = b[k]; b[k] = b[p]; b[p] = tmp; } }
  int j = 0;
  for (; j + 4 <= n; j += 4) {
    /* four columns per pass: b[j..j+3] final within the block first, then the rows below
     * take the four terms in turn (fewer loads and stores of b) */
    const double *c0 = lt + j * n, *c1 = c0 + n, *c2 = c1 + n, *c3 = c2 + n;
    double b0 = b[j];
    double b1 = b[j + 1] - c0[j + 1] * b0;
    double b2 = b[j + 2] - c0[j + 2] * b0; b2 -= c1[j + 2] * b1;
    double b3 = b[j + 3] - c0[j + 3] * b0; b3 -= c1[j + 3] * b1; b3 -= c2[j + 3] * b2;
    b[j + 1] = b1; b[j + 2] = b2; b[j + 3] = b3;
    for (int i = j + 4; i < n; ++i) {
      double r = b[i];
      r -= c0[i] * b0; r -= c1[i] * b1; r -= c2[i] * b2; r -= c3[i] * b3;
      b[i] = r;
    }
  }
  for (; j < n - 1; ++j) {
    const double *col = lt + j * n;
    double bj = b[j];
    for (int i = j + 1; i < n; ++i) b[i] -= col[i] * bj;
  }
  for (int i = n - 1; i >= 0; --i) { double sum = b[i]; for (int j = i + 1; j < n; ++j) sum -= a[i * n + j] * b[j]; b[i] = sum / a[i * n + i]; }
}

/* ---- BDF machinery -------------------------------------------------------------------------- */

static const double KAPPA[MAX_ORDER + 1] = {0.0, -0.1850, -1.0 / 9.0, -0.0823, -0.0415, 0.0};
static double GAMMA[MAX_ORDER + 2], ALPHA[MAX_ORDER + 1], ERRCONST[MAX_ORDER + 2];

static void bdf_constants(void) {
  GAMMA[0] = 0.0;
  for (int k = 1; k <= MAX_ORDER + 1; ++k) GAMMA[k] = GAMMA[k - 1] + 1.0 / k;
  for (int k = 0; k <= MAX_ORDER; ++k) {
    ALPHA[k] = (1.0 - KAPPA[k]) * GAMMA[k];
    ERRCONST[k] = KAPPA[k] * GAMMA[k] + 1.0 / (k + 1);
  }
  ERRCONST[MAX_ORDER + 1] = 1.0 / (MAX_ORDER + 2);
}

/* R(order, factor): the matrix that rescales differences to a step factor * h. */
static void compute_r(int order, double factor, double *r /* (order+1)^2 */) {
  int m = order + 1;
  for (int j = 0; j < m; ++j) r[j] = 1.0;
  for (int i = 1; i < m; ++i)
    for (int j = 0; j < m; ++j)
      r[i * m + j] = j == 0 ? 0.0 : r[(i - 1) * m + j] * (i - 1 - factor * j) / i;
  /* row 0 stays 1 except its first entry, which the cumulative product keeps at 1 */
}

static void change_d(jp_sim *s, double factor) {
  int m = s->order + 1, N = s->N;
  double R[(MAX_ORDER + 1) * (MAX_ORDER + 1)], U[(MAX_ORDER + 1) * (MAX_ORDER + 1)];
  double RU[(MAX_ORDER + 1) * (MAX_ORDER + 1)];
  compute_r(s->order, factor, R);
  compute_r(s->order, 1.0, U);
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) {
      double sum = 0.0;
      for (int k = 0; k < m; ++k) sum += R[i * m + k] * U[k * m + j];
      RU[i * m + j] = sum;
    }
  /* D[:m] = RU^T D[:m] */
  double *tmp = s->work_n; /* needs m * N: work_n has (MAX_ORDER + 3) * N */
  for (int i = 0; i < m; ++i) { /* row by row: each entry's terms in turn, k ascending */
    double *out = tmp + i * N;
    for (int col = 0; col < N; ++col) out[col] = 0.0;
    for (int k = 0; k < m; ++k) {
      const double *row = s->D + k * N;
      double r = RU[k * m + i];
      for (int col = 0; col < N; ++col) out[col] += r * row[col];
    }
  }
  memcpy(s->D, tmp, (size_t)m * N * sizeof(double));
}

/* Dense output of the last step at time t into y: its first n values (n <= N; the state part
 * alone is n = nx). The product p vanishes from the factor whose shift is t on (t at the end of
 * the step, or at its start), and adding a zero term changes nothing: the loop stops there. */
static void dense_first(const jp_sim *s, double t, double *y, int n) {
  int N = s->N, order = s->order;
  memcpy(y, s->D, n * sizeof(double));
  double p = 1.0;
  for (int k = 0; k < order; ++k) {
    double shift = s->t - s->h * k, denom = s->h * (1 + k);
    p *= (t - shift) / denom;
    if (p == 0.0) break;
    const double *row = s->D + (k + 1) * N;
    for (int i = 0; i < n; ++i) y[i] += p * row[i];
  }
}

/* Dense output of the last step at time t into y (N values). */
static void dense(const jp_sim *s, double t, double *y) { dense_first(s, t, y, s->N); }

/* The scaled state Jacobian at (t, z) into J (nx x nx, row-major). */
static int jacobian_values(jp_sim *s, double t, const double *z, double *J) {
  const jp_config *c = &s->c;
  int nx = c->nx;
  if (torques_at(s, t)) return 1;
  unscale(s, z);
  s->arg[0] = s->xs; s->arg[1] = s->tau; s->arg[2] = c->p; s->arg[3] = s->v_imp;
  s->arg[4] = NULL;
  s->res[0] = s->jac_sparse;
  for (int k = 1; k < c->jac.n_out; ++k) s->res[k] = NULL;
  if (call(s, &c->jac)) return 1;
  memset(J, 0, (size_t)nx * nx * sizeof(double));
  const jp_int *sp = c->jac.sparsity_out0; /* nrow, ncol, colind[ncol+1], row[nnz] */
  jp_int ncol = sp[1];
  const jp_int *colind = sp + 2, *row = sp + 2 + ncol + 1;
  for (jp_int col = 0; col < ncol; ++col)
    for (jp_int k = colind[col]; k < colind[col + 1]; ++k) {
      jp_int r = row[k];
      /* scaled: dz_r/dz_col = J_rc * scale_col / scale_r */
      J[r * nx + col] = s->jac_sparse[k] * c->scale[col] / c->scale[r];
    }
  return 0;
}

static int jacobian(jp_sim *s, double t, const double *z) {
  int nx = s->c.nx;
  if (jacobian_values(s, t, z, s->J)) return 1;
  s->n_jac++;
  int n = nx / 2;
  s->reduced = nx % 2 == 0 && s->newton != JP_NEWTON_FULL
              && (s->newton == JP_NEWTON_REDUCED || n >= JP_REDUCED_NEWTON_FROM);
  for (int r = 0; r < n && s->reduced; ++r)
    for (int col = 0; col < nx; ++col)
      if (col != n + r && s->J[r * nx + col] != 0.0) { s->reduced = 0; break; }
  /* Jq by columns, for newton_solve (once per Jacobian, not per factorisation) */
  if (s->reduced)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) s->JqT[j * n + i] = s->J[(size_t)(n + i) * nx + j];
  return all_finite(nx * nx, s->J) ? 0 : 1;
}

/* Factor the Newton matrix I - c J (see jp_sim.reduced). Returns nonzero when singular. */
static int newton_factor(jp_sim *s, double c_coef) {
  int nx = s->c.nx, n = nx / 2;
  s->lu_c = c_coef;
  s->n_lu++;
  if (!s->reduced) {
    for (int i = 0; i < nx * nx; ++i) s->LU[i] = -c_coef * s->J[i];
    for (int i = 0; i < nx; ++i) s->LU[i * nx + i] += 1.0;
    if (lu_factor(nx, s->LU, s->piv)) return 1;
    lu_lower_columns(nx, s->LU, s->LT);
    return 0;
  }
  s->n_lu_reduced++;
  for (int i = 0; i < n; ++i) {
    const double *jq = s->J + (size_t)(n + i) * nx, *jv = jq + n;
    for (int j = 0; j < n; ++j)
      s->LU[i * n + j] = (i == j) - c_coef * jv[j]
                         - c_coef * c_coef * jq[j] * s->J[(size_t)j * nx + n + j];
  }
  if (lu_factor(n, s->LU, s->piv)) return 1;
  lu_lower_columns(n, s->LU, s->LT);
  return 0;
}

/* b <- (I - c J)^-1 b with the factors of newton_factor. */
static void newton_solve(jp_sim *s, double *b) {
  int nx = s->c.nx, n = nx / 2;
  if (!s->reduced) { lu_solve(nx, s->LU, s->LT, s->piv, b); return; }
  double c_coef = s->lu_c;
  /* rhs_u = b_u + c Jq b_q, column by column: each row's terms in the order of its dot
   * product (j ascending), the rows' updates independent */
  double *u = s->rhs_u;
  for (int i = 0; i < n; ++i) u[i] = b[n + i];
  int j = 0;
  for (; j + 4 <= n; j += 4) { /* four columns per pass: fewer loads and stores of u */
    const double *c0 = s->JqT + (size_t)j * n, *c1 = c0 + n, *c2 = c1 + n, *c3 = c2 + n;
    double b0 = b[j], b1 = b[j + 1], b2 = b[j + 2], b3 = b[j + 3];
    for (int i = 0; i < n; ++i) {
      double r = u[i];
      r += c_coef * c0[i] * b0; r += c_coef * c1[i] * b1;
      r += c_coef * c2[i] * b2; r += c_coef * c3[i] * b3;
      u[i] = r;
    }
  }
  for (; j < n; ++j) {
    const double *col = s->JqT + (size_t)j * n;
    double bj = b[j];
    for (int i = 0; i < n; ++i) u[i] += c_coef * col[i] * bj;
  }
  lu_solve(n, s->LU, s->LT, s->piv, s->rhs_u);
  for (int i = 0; i < n; ++i) {
    b[n + i] = s->rhs_u[i];
    b[i] += c_coef * s->J[(size_t)i * nx + n + i] * s->rhs_u[i];
  }
}

static void quad_scale(jp_sim *s, const double *y, double *scal) {
  for (int i = 0; i < s->c.nx; ++i) scal[i] = s->c.atol + s->c.rtol * fabs(y[i]);
}

/* ---- forward sensitivities -------------------------------------------------------------------- */
/* S = dx/dp for ns named parameters, each a direction dp in the parameter vector, solves the
 * linear system S' = f_x S + f_p dp + f_v dv_imp/dp. The staggered direct method (Caracotsios
 * and Stewart, Comput. Chem. Eng. 9, 1985): after each accepted step of the state, S at the
 * step's end solves the same BDF formula, with f_x and f_p at the converged state and its own
 * Newton matrix I - c f_x (exact in one solve; the state's LU may hold a stale Jacobian).
 * S rides in D beside the state (so the dense output, step changes and redone steps carry
 * it), by default outside the error test: the state's steps are those of a run without it
 * (with sens_errcon, in it: see sens_norm). At a
 * contact onset (an event g = |e| - c(p) = 0 at tau) the event time moves by
 * dtau/dp = -(g_x S + g_p) / (g_x f), S jumps by (f- - f+) dtau/dp (Hiskens and Pai, IEEE
 * TCAS-I 47, 2000), and the captured approach speed's derivative, d(delta_dot(x(tau)))/dp,
 * is carried as a parameter's until the joint's next onset. */

/* A phase's sensitivity record: dtau/dp (ns), then at its force peak the state (nx), S
 * (ns x nx, unscaled), the impact speeds (nc) and their derivatives (nc x ns). */
static int sens_record_size(const jp_config *c) {
  return c->ns + c->nx + c->ns * c->nx + c->nc + c->nc * c->ns;
}

/* dz/dt at (t, z) with the current impact speeds, not counted as a step's evaluation. */
static int model_rates(jp_sim *s, double t, const double *z, double *dz) {
  const jp_config *c = &s->c;
  if (torques_at(s, t)) return 1;
  unscale(s, z);
  s->arg[0] = s->xs; s->arg[1] = s->tau; s->arg[2] = c->p; s->arg[3] = s->v_imp;
  s->res[0] = s->xdot;
  if (call(s, &c->f)) return 1;
  for (int i = 0; i < c->nx; ++i) dz[i] = s->xdot[i] / c->scale[i];
  return all_finite(c->nx, dz) ? 0 : 1;
}

/* bz as sens_forcing's, from forward_dynamics_input_directions: dir_k directions a call, each
 * seed column a parameter's direction dp and its impact speeds' derivatives. */
static int sens_forcing_directional(jp_sim *s) {
  const jp_config *c = &s->c;
  int nx = c->nx, ns = c->ns, np = c->np, nc = c->nc, k = c->dir_k, rows = np + nc;
  for (int q0 = 0; q0 < ns; q0 += k) {
    memset(s->seeds, 0, (size_t)rows * k * sizeof(double));
    for (int col = 0; col < k && q0 + col < ns; ++col) {
      int q = q0 + col;
      memcpy(s->seeds + (size_t)col * rows, c->dp + (size_t)q * np, (size_t)np * sizeof(double));
      for (int j = 0; j < nc; ++j) s->seeds[(size_t)col * rows + np + j] = s->v_sens[j * ns + q];
    }
    s->arg[0] = s->xs; s->arg[1] = s->tau; s->arg[2] = c->p; s->arg[3] = s->v_imp;
    s->arg[4] = s->seeds;
    s->res[0] = s->dir_out;
    if (call(s, &c->dir_in)) return 1;
    for (int col = 0; col < k && q0 + col < ns; ++col)
      for (int r = 0; r < nx; ++r)
        s->bz[(q0 + col) * nx + r] = s->dir_out[(size_t)col * nx + r] / c->scale[r];
  }
  return all_finite(ns * nx, s->bz) ? 0 : 1;
}

/* bz (ns x nx, scaled): f_p dp + f_v dv_imp/dp at (t, z), from jac_forward_dynamics_inputs
 * (or along the directions alone, where the model has forward_dynamics_input_directions). */
static int sens_forcing(jp_sim *s, double t, const double *z) {
  const jp_config *c = &s->c;
  int nx = c->nx, ns = c->ns, np = c->np, nc = c->nc;
  if (torques_at(s, t)) return 1;
  unscale(s, z);
  if (c->dir_in.eval) return sens_forcing_directional(s);
  s->arg[0] = s->xs; s->arg[1] = s->tau; s->arg[2] = c->p; s->arg[3] = s->v_imp;
  for (int k = 0; k < c->jac_in.n_out; ++k) s->res[k] = NULL;
  s->res[1] = s->fp_sparse;
  if (nc) s->res[2] = s->fv_sparse;
  if (call(s, &c->jac_in)) return 1;
  memset(s->bz, 0, (size_t)ns * nx * sizeof(double));
  const jp_int *patterns[2] = {c->sp_p, nc ? c->sp_v : NULL};
  const double *values[2] = {s->fp_sparse, s->fv_sparse};
  for (int b = 0; b < 2; ++b) {
    const jp_int *sp = patterns[b];
    if (!sp) continue;
    jp_int ncol = sp[1];
    const jp_int *colind = sp + 2, *row = sp + 2 + ncol + 1;
    for (jp_int col = 0; col < ncol; ++col)
      for (jp_int k = colind[col]; k < colind[col + 1]; ++k) {
        jp_int r = row[k];
        double v = values[b][k];
        for (int q = 0; q < ns; ++q) {
          double dir = b == 0 ? c->dp[(size_t)q * np + col] : s->v_sens[col * ns + q];
          s->bz[q * nx + r] += v * dir;
        }
      }
  }
  for (int q = 0; q < ns; ++q)
    for (int r = 0; r < nx; ++r) s->bz[q * nx + r] /= c->scale[r];
  return all_finite(ns * nx, s->bz) ? 0 : 1;
}

/* Z' = Js Z + bz for each sensitivity block of the N-vector y, into out (same layout). */
static void sens_rates(const jp_sim *s, const double *y, double *out) {
  int nx = s->c.nx;
  for (int q = 0; q < s->c.ns; ++q) {
    int o = s->sens_col + q * nx;
    for (int i = 0; i < nx; ++i) {
      const double *ji = s->Js + (size_t)i * nx;
      double sum = 0.0;
      for (int j = 0; j < nx; ++j) sum += ji[j] * y[o + j];
      out[o + i] = sum + s->bz[q * nx + i];
    }
  }
}

/* The sensitivities at the end of the step just accepted (state y_new at t_new, predictor
 * y_pred, psi and c of the step): d = y_new - y_pred of each block from
 * (I - c Js) d = c (Js y_pred + bz) - psi. */
static int sens_step(jp_sim *s, double t_new, double c_coef) {
  const jp_config *c = &s->c;
  int nx = c->nx;
  if (jacobian_values(s, t_new, s->y_new, s->Js) || sens_forcing(s, t_new, s->y_new)) return 1;
  s->n_sens_jac++;
  for (int i = 0; i < nx * nx; ++i) s->LUs[i] = -c_coef * s->Js[i];
  for (int i = 0; i < nx; ++i) s->LUs[i * nx + i] += 1.0;
  if (lu_factor(nx, s->LUs, s->pivs)) return 1;
  lu_lower_columns(nx, s->LUs, s->LTs);
  sens_rates(s, s->y_pred, s->sens_tmp);
  for (int q = 0; q < c->ns; ++q) {
    int o = s->sens_col + q * nx;
    double *dz = s->d + o;
    for (int i = 0; i < nx; ++i) dz[i] = c_coef * s->sens_tmp[o + i] - s->psi[o + i];
    lu_solve(nx, s->LUs, s->LTs, s->pivs, dz);
    for (int i = 0; i < nx; ++i) s->y_new[o + i] = s->y_pred[o + i] + dz[i];
  }
  return all_finite(c->ns * nx, s->d + s->sens_col) ? 0 : 1;
}

/* The largest RMS norm over the sensitivity blocks of factor * e (an N-vector of corrections
 * or differences) with weights atol / sens_scale + rtol |y| (y: the N-vector they belong to). */
static double sens_norm(const jp_sim *s, double factor, const double *e, const double *y) {
  const jp_config *c = &s->c;
  int nx = c->nx;
  double norm = 0.0;
  for (int q = 0; q < c->ns; ++q) {
    int o = s->sens_col + q * nx;
    double floor = c->atol / c->sens_scale[q], sum = 0.0;
    for (int i = 0; i < nx; ++i) {
      double v = factor * e[o + i] / (floor + c->rtol * fabs(y[o + i]));
      sum += v * v;
    }
    norm = fmax(norm, sqrt(sum / nx));
  }
  return norm;
}

/* At the onset of joint j at t (y: the N-vector there, a copy of D's first row; v_old: the
 * impact speed before this onset captured v_imp[j]): the event time's derivative (located:
 * 0 for a contact present at the start), the jump of S in D's first row and the new impact
 * speed's derivative. */
static void sens_onset(jp_sim *s, int j, double t, const double *y, double v_old,
                       int located) {
  const jp_config *c = &s->c;
  int nx = c->nx, nq = c->nq, ns = c->ns, nc = c->nc;
  double v_new = s->v_imp[j];
  s->v_imp[j] = v_old;
  int bad = model_rates(s, t, y, s->f_minus);
  s->v_imp[j] = v_new;
  bad |= model_rates(s, t, y, s->f_plus);
  if (bad) { s->status = JP_NONFINITE; s->fail_t = t; s->fail_joint = j; return; }
  int ix = c->ecc_index[2 * j], iy = c->ecc_index[2 * j + 1];
  const double *sc = c->scale;
  double ex = y[ix] * sc[ix], ey = y[iy] * sc[iy];
  double vx = y[nq + ix] * sc[nq + ix], vy = y[nq + iy] * sc[nq + iy];
  double ax = s->f_minus[nq + ix] * sc[nq + ix], ay = s->f_minus[nq + iy] * sc[nq + iy];
  double floor = 1e-6 * c->clearance[j];
  double e = sqrt(fmax(ex * ex + ey * ey, floor * floor));
  double rate = (ex * vx + ey * vy) / e;
  double *record = s->open_phase[j] >= 0
                   ? s->phase_sens + (size_t)s->open_phase[j] * s->sens_record : NULL;
  for (int q = 0; q < ns; ++q) {
    int o = s->sens_col + q * nx;
    double sex = y[o + ix] * sc[ix], sey = y[o + iy] * sc[iy];
    double svx = y[o + nq + ix] * sc[nq + ix], svy = y[o + nq + iy] * sc[nq + iy];
    double dtau = located ? -((ex * sex + ey * sey) / e - c->dc[q * nc + j]) / rate : 0.0;
    /* the state at the moved event: x(tau(p), p), its derivative S + f- dtau/dp */
    double dex = sex + vx * dtau, dey = sey + vy * dtau;
    double dvx = svx + ax * dtau, dvy = svy + ay * dtau;
    s->v_sens[j * ns + q] = (vx / e - rate * ex / (e * e)) * dex
                            + (vy / e - rate * ey / (e * e)) * dey + ex / e * dvx + ey / e * dvy;
    for (int i = 0; i < nx; ++i) s->D[o + i] += (s->f_minus[i] - s->f_plus[i]) * dtau;
    if (record) record[q] = dtau;
  }
}

/* A new force peak of joint j's open phase at t (on the last step's dense output): the state,
 * sensitivities and impact speeds there, for the peak's derivative. */
static void sens_peak(jp_sim *s, int j, double t) {
  const jp_config *c = &s->c;
  int nx = c->nx, ns = c->ns, nc = c->nc;
  if (s->open_phase[j] < 0) return;
  double *x = s->phase_sens + (size_t)s->open_phase[j] * s->sens_record + ns;
  double *S = x + nx, *v = S + (size_t)ns * nx;
  dense(s, t, s->sens_tmp);
  for (int i = 0; i < nx; ++i) x[i] = s->sens_tmp[i] * c->scale[i];
  for (int q = 0; q < ns; ++q)
    for (int i = 0; i < nx; ++i)
      S[q * nx + i] = s->sens_tmp[s->sens_col + q * nx + i] * c->scale[i];
  memcpy(v, s->v_imp, nc * sizeof(double));
  memcpy(v + nc, s->v_sens, (size_t)nc * ns * sizeof(double));
}

/* Start (or restart) at (t, z): order 1, a step from the initial-step heuristic. */
static int bdf_start(jp_sim *s, double t, const double *z, const double *quad, double t_bound) {
  const jp_config *c = &s->c;
  int N = s->N, nx = c->nx;
  memset(s->D, 0, (size_t)(MAX_ORDER + 3) * N * sizeof(double));
  memcpy(s->D, z, nx * sizeof(double));
  memcpy(s->D + nx, quad, s->nquad * sizeof(double));
  /* z is a whole N-vector: its sensitivity blocks follow the quadratures */
  if (c->ns) memcpy(s->D + s->sens_col, z + s->sens_col, (size_t)c->ns * nx * sizeof(double));
  double *f0 = s->f_buf, *f1 = s->dy, *y1 = s->tmp_y;
  int rc = rhs(s, t, z, f0);
  if (rc) { if (rc > 0) { s->status = JP_NONFINITE; s->fail_t = t; } return 1; }
  double h;
  if (c->h_init > 0) {
    h = c->h_init;
  } else {
    quad_scale(s, z, s->scal);
    double d0 = rms(nx, z, s->scal), d1 = rms(nx, f0, s->scal);
    double h0 = (d0 < 1e-5 || d1 < 1e-5) ? 1e-6 : 0.01 * d0 / d1;
    for (int i = 0; i < nx; ++i) y1[i] = z[i] + h0 * f0[i];
    rc = rhs(s, t + h0, y1, f1);
    if (rc) { if (rc > 0) { s->status = JP_NONFINITE; s->fail_t = t; } return 1; }
    for (int i = 0; i < nx; ++i) f1[i] -= f0[i];
    double d2 = rms(nx, f1, s->scal) / h0;
    double h1 = (d1 <= 1e-15 && d2 <= 1e-15) ? fmax(1e-6, h0 * 1e-3)
                                              : pow(0.01 / fmax(d1, d2), 0.5);
    h = fmin(100 * h0, h1);
  }
  h = fmin(h, c->h_max);
  if (t_bound > t) h = fmin(h, t_bound - t);
  /* quadrature rates at the start (torques are at t from the first rhs call) */
  rc = torques_at(s, t);
  quadrature_rates(s, t, z, s->tmp_y2);
  if (c->nc) {
    memcpy(s->fn_carry, s->fn_quad, c->nc * sizeof(double));
    s->fn_carry_t = t; s->fn_carry_gen = s->v_gen;
  }
  for (int i = 0; i < nx; ++i) s->D[N + i] = f0[i] * h;
  for (int i = 0; i < s->nquad; ++i) s->D[N + nx + i] = s->tmp_y2[i] * h;
  s->t = t; s->h_abs = h; s->h = h; s->order = 1; s->n_equal_steps = 0;
  s->have_lu = 0; s->current_jac = 0; s->started = 1;
  if (jacobian(s, t, z)) { s->status = JP_NONFINITE; s->fail_t = t; return 1; }
  s->current_jac = 1;
  if (c->ns) {
    memcpy(s->Js, s->J, (size_t)nx * nx * sizeof(double));
    if (sens_forcing(s, t, z)) { s->status = JP_NONFINITE; s->fail_t = t; return 1; }
    sens_rates(s, s->D, s->sens_tmp);
    for (int i = s->sens_col; i < N; ++i) s->D[N + i] = s->sens_tmp[i] * h;
  }
  return 0;
}

/* One Newton solve of the BDF system. Returns 1 when converged. */
static int newton(jp_sim *s, double t_new, double c_coef, double tol, int *iters) {
  const jp_config *c = &s->c;
  int nx = c->nx;
  memset(s->d, 0, nx * sizeof(double));
  memcpy(s->y_new, s->y_pred, nx * sizeof(double));
  double dy_norm_old = -1.0;
  for (int k = 0; k < NEWTON_MAXITER; ++k) {
    *iters = k + 1;
    int rc = rhs(s, t_new, s->y_new, s->f_buf);
    if (rc < 0) return -1; /* bad torque: fatal */
    if (rc) return 0;
    for (int i = 0; i < nx; ++i) s->dy[i] = c_coef * s->f_buf[i] - s->psi[i] - s->d[i];
    newton_solve(s, s->dy);
    double dy_norm = rms(nx, s->dy, s->scal);
    double rate = dy_norm_old > 0 ? dy_norm / dy_norm_old : -1.0;
    if (rate >= 0 && (rate >= 1 || pow(rate, NEWTON_MAXITER - k) / (1 - rate) * dy_norm > tol))
      return 0;
    for (int i = 0; i < nx; ++i) { s->y_new[i] += s->dy[i]; s->d[i] += s->dy[i]; }
    if (dy_norm == 0 || (rate >= 0 && rate / (1 - rate) * dy_norm < tol)) return 1;
    dy_norm_old = dy_norm;
  }
  return 0;
}

/* Take one step, not past t_bound. Returns 0 on success (the step is in s->D, s->t), else 1
 * with s->status set. On success the pre-step differences are kept in D_save for a redo. */
static int bdf_step(jp_sim *s, double t_bound) {
  const jp_config *c = &s->c;
  int N = s->N, nx = c->nx, nq = s->nquad;
  double newton_tol = fmax(10 * 2.220446049250313e-16 / c->rtol, fmin(0.03, sqrt(c->rtol)));
  double h_abs = s->h_abs;
  if (h_abs > c->h_max) { change_d(s, c->h_max / h_abs); h_abs = c->h_max; s->have_lu = 0; }
  for (;;) {
    double min_step = 16 * 2.220446049250313e-16 * fmax(fabs(s->t), 1e-300);
    if (h_abs < min_step || h_abs < 1e-15) {
      s->status = JP_STEP_COLLAPSED; s->fail_t = s->t; s->fail_h = h_abs; return 1;
    }
    double h = h_abs, t_new = s->t + h;
    /* land on the bound, stretching a step that would leave a sliver of it: a remainder of
     * round-off size would otherwise be a step of its own, below the smallest allowed */
    if (t_new > t_bound || t_bound - t_new < 1e-3 * h) {
      t_new = t_bound; h = t_new - s->t;
      change_d(s, h / h_abs); h_abs = h; s->have_lu = 0;
    }
    int order = s->order;
    /* predictor and psi: sums over the differences, row by row (contiguous; each entry's
     * terms in the same order, k ascending) */
    for (int i = 0; i < N; ++i) s->y_pred[i] = 0.0 + s->D[i];
    for (int k = 1; k <= order; ++k) {
      const double *row = s->D + k * N;
      for (int i = 0; i < N; ++i) s->y_pred[i] += row[i];
    }
    quad_scale(s, s->y_pred, s->scal);
    for (int i = 0; i < N; ++i) s->psi[i] = 0.0;
    for (int k = 1; k <= order; ++k) {
      const double *row = s->D + k * N;
      for (int i = 0; i < N; ++i) s->psi[i] += row[i] * GAMMA[k];
    }
    for (int i = 0; i < N; ++i) s->psi[i] /= ALPHA[order];
    double c_coef = h / ALPHA[order];
    int converged = 0, iters = 0;
    for (;;) {
      if (!s->have_lu) {
        if (newton_factor(s, c_coef)) { converged = 0; s->have_lu = 0; break; }
        s->have_lu = 1;
      }
      converged = newton(s, t_new, c_coef, newton_tol, &iters);
      if (converged < 0) return 1;
      if (converged || s->current_jac) break;
      if (jacobian(s, t_new, s->y_pred)) break;
      s->current_jac = 1; s->have_lu = 0;
    }
    if (!converged) {
      s->n_newton_fail++;
      change_d(s, 0.5); h_abs *= 0.5; s->n_equal_steps = 0; s->have_lu = 0;
      continue;
    }
    double safety = 0.9 * (2 * NEWTON_MAXITER + 1) / (2 * NEWTON_MAXITER + iters);
    quad_scale(s, s->y_new, s->scal);
    for (int i = 0; i < nx; ++i) s->err[i] = ERRCONST[order] * s->d[i];
    double err_norm = rms(nx, s->err, s->scal);
    if (c->ns && c->sens_errcon) {
      /* the sensitivities first, so that their error counts in the test */
      if (sens_step(s, t_new, c_coef)) {
        s->status = JP_NONFINITE; s->fail_t = t_new; s->fail_h = h; return 1;
      }
      err_norm = fmax(err_norm, sens_norm(s, ERRCONST[order], s->d, s->y_new));
    }
    s->last_err_norm = err_norm;
    if (err_norm > 1.0) {
      s->n_err_fail++;
      s->recent_failures++;
      double factor = fmax(0.2, safety * pow(err_norm, -1.0 / (order + 1)));
      change_d(s, factor); h_abs *= factor; s->n_equal_steps = 0; s->have_lu = 0;
      continue;
    }
    /* accepted: quadratures explicitly at the converged state */
    torques_at(s, t_new);
    quadrature_rates(s, t_new, s->y_new, s->tmp_y2);
    for (int i = 0; i < nq; ++i) {
      double di = c_coef * s->tmp_y2[i] - s->psi[nx + i];
      s->d[nx + i] = di;
      s->y_new[nx + i] = s->y_pred[nx + i] + di;
    }
    if (c->ns && !c->sens_errcon && sens_step(s, t_new, c_coef)) {
      s->status = JP_NONFINITE; s->fail_t = t_new; s->fail_h = h; return 1;
    }
    /* rows 0..order+2 are all a step at this order reads or writes (those above are written
     * before they are read, should the order rise): the rest need no copy for a redo */
    memcpy(s->D_save, s->D, (size_t)(order + 3) * N * sizeof(double));
    s->t_old = s->t; s->h_abs_old = h_abs; s->order_old = order;
    s->n_equal_old = s->n_equal_steps;
    s->n_steps++;
    s->n_equal_steps++;
    s->t = t_new; s->h = h; s->h_abs = h_abs;
    s->current_jac = 0;
    double *D = s->D;
    for (int i = 0; i < N; ++i) {
      D[(order + 2) * N + i] = s->d[i] - D[(order + 1) * N + i];
      D[(order + 1) * N + i] = s->d[i];
    }
    for (int k = order; k >= 0; --k)
      for (int i = 0; i < N; ++i) D[k * N + i] += D[(k + 1) * N + i];
    s->last_safety = safety;
    return 0;
  }
}

/* After an accepted step (and its events): choose the order and step of the next one. */
static void bdf_adapt(jp_sim *s) {
  int order = s->order, N = s->N, nx = s->c.nx;
  /* Stability limit: BDF of order 3 and above is not A-stable, and a lightly damped contact
   * vibration (eigenvalues near the imaginary axis) then makes the steps saw up and down
   * through error-test failures. Repeated failures at such an order cap it at 2 (A-stable)
   * for a while; the cap is lifted again once the steps run clean. */
  if (++s->window_steps >= STABILITY_WINDOW) {
    if (s->recent_failures * STABILITY_FAILURE_SHARE >= s->window_steps && s->order >= 3)
      s->order_cap = STABILITY_ORDER, s->cap_steps = STABILITY_HOLD;
    s->window_steps = 0; s->recent_failures = 0;
  }
  if (s->cap_steps > 0 && --s->cap_steps == 0) s->order_cap = s->c.max_order;
  if (s->order > s->order_cap) {
    s->order = s->order_cap; s->n_equal_steps = 0; s->have_lu = 0;
    return;
  }
  if (s->n_equal_steps < order + 1) return;
  quad_scale(s, s->D, s->scal); /* D[0] is the current point */
  double norms[3] = {INFINITY, s->last_err_norm, INFINITY};
  int sens = s->c.ns && s->c.sens_errcon;
  if (order > 1) {
    for (int i = 0; i < nx; ++i) s->err[i] = ERRCONST[order - 1] * s->D[order * N + i];
    norms[0] = rms(nx, s->err, s->scal);
    if (sens)
      norms[0] = fmax(norms[0], sens_norm(s, ERRCONST[order - 1], s->D + order * N, s->D));
  }
  if (order < s->order_cap) {
    for (int i = 0; i < nx; ++i) s->err[i] = ERRCONST[order + 1] * s->D[(order + 2) * N + i];
    norms[2] = rms(nx, s->err, s->scal);
    if (sens)
      norms[2] = fmax(norms[2], sens_norm(s, ERRCONST[order + 1], s->D + (order + 2) * N, s->D));
  }
  int best = 1; double best_factor = 0.0;
  for (int k = 0; k < 3; ++k) {
    double f = norms[k] == 0.0 ? INFINITY : pow(norms[k], -1.0 / (order + k));
    if (isnan(f)) f = 0.0;
    if (f > best_factor) { best_factor = f; best = k; }
  }
  s->order = order + best - 1;
  double factor = fmin(10.0, s->last_safety * best_factor);
  change_d(s, factor);
  s->h_abs *= factor; s->n_equal_steps = 0; s->have_lu = 0;
}

/* ---- events ---------------------------------------------------------------------------------- */

enum { EV_DELTA = 0, EV_RATE = 1 };

/* The event function `kind` of joint j at time t, on the dense output of the last step. */
static double event_value(jp_sim *s, int kind, int j, double t) {
  dense_first(s, t, s->tmp_y, s->c.nx);
  unscale(s, s->tmp_y);
  double delta, rate;
  gap(s, s->xs, j, &delta, &rate);
  return kind == EV_DELTA ? delta : rate;
}

/* Illinois regula falsi for a sign change of the event function in [a, b]: returns the end of
 * the final bracket on b's side (where the sign is that of fb). */
static double locate(jp_sim *s, int kind, int j, double a, double fa, double b, double fb,
                     double *at_root) {
  int side = 0;
  double ttol = 4 * 2.220446049250313e-16 * fmax(fabs(a), fabs(b));
  for (int it = 0; it < 200 && b - a > ttol; ++it) {
    double m = (a * fb - b * fa) / (fb - fa);
    if (!(m > a && m < b)) m = 0.5 * (a + b);
    /* keep the iterate away from the ends so the bracket always shrinks */
    double w = b - a;
    if (m - a < 1e-3 * w) m = a + 1e-3 * w;
    if (b - m < 1e-3 * w) m = b - 1e-3 * w;
    double fm = event_value(s, kind, j, m);
    if ((fm > 0) == (fb > 0)) {
      b = m; fb = fm;
      if (side == -1) fa *= 0.5;
      side = -1;
    } else {
      a = m; fa = fm;
      if (side == 1) fb *= 0.5;
      side = 1;
    }
  }
  if (at_root) *at_root = fb;
  return b;
}

static int new_phase(jp_sim *s, int j, double t, double speed, const double *xs) {
  if (s->n_phases == s->cap_phases) {
    long cap = s->cap_phases ? 2 * s->cap_phases : 64;
    double *grown = realloc(s->phases, (size_t)cap * PH_FIELDS * sizeof(double));
    if (!grown) { s->status = JP_NO_MEMORY; return 1; }
    s->phases = grown;
    if (s->c.ns) {
      grown = realloc(s->phase_sens, (size_t)cap * s->sens_record * sizeof(double));
      if (!grown) { s->status = JP_NO_MEMORY; return 1; }
      s->phase_sens = grown;
    }
    s->cap_phases = cap;
  }
  if (s->c.ns) { /* nothing known yet: no event-time change, no peak (state NAN) */
    double *rec = s->phase_sens + (size_t)s->n_phases * s->sens_record;
    for (int k = 0; k < s->sens_record; ++k) rec[k] = 0.0;
    for (int k = 0; k < s->c.nx; ++k) rec[s->c.ns + k] = NAN;
  }
  double *row = s->phases + s->n_phases * PH_FIELDS;
  for (int k = 0; k < PH_FIELDS; ++k) row[k] = NAN;
  const jp_config *c = &s->c;
  row[PH_JOINT] = j; row[PH_T_ON] = t; row[PH_V_ON] = speed;
  if (c->gap_fn.eval) {
    model_gaps(s, xs);
    row[PH_EX] = s->g_out[2 * c->nc + j]; row[PH_EY] = s->g_out[3 * c->nc + j];
  } else {
    row[PH_EX] = xs[c->ecc_index[2 * j]]; row[PH_EY] = xs[c->ecc_index[2 * j + 1]];
  }
  if (c->peaks) row[PH_F_PEAK] = 0.0;
  row[PH_D_MAX] = 0.0;
  s->open_phase[j] = s->n_phases++;
  s->n_onsets++;
  return 0;
}

/* Quadrature block index of joint j's impulse / damping / friction. */
static int quad_index(const jp_sim *s, int j, int which) { return s->c.nx + 1 + 3 * j + which; }

/* Store cumulative quadratures at phase start as negative values; close adds the end values. */
static void phase_quadratures(jp_sim *s, double *row, const double *y, int j, double sign) {
  double *cols[3] = {&row[PH_IMPULSE], &row[PH_DAMPING], &row[PH_FRICTION]};
  for (int k = 0; k < 3; ++k) {
    double v = sign * y[quad_index(s, j, k)];
    *cols[k] = isnan(*cols[k]) ? v : *cols[k] + v;
  }
}

static void onset(jp_sim *s, int j, double t, const double *y /* scaled, N */,
                  int located) {
  unscale(s, y);
  double delta, rate, v_old = s->v_imp[j];
  gap(s, s->xs, j, &delta, &rate);
  s->flags[j] = 1.0; s->armed[j] = delta > 0; s->v_imp[j] = rate; s->rising[j] = 1;
  s->v_gen++;
  s->n_events++;
  if (new_phase(s, j, t, rate, s->xs)) return;
  phase_quadratures(s, s->phases + s->open_phase[j] * PH_FIELDS, y, j, -1.0);
  if (s->c.ns) sens_onset(s, j, t, y, v_old, located);
}

static void separation(jp_sim *s, int j, double t) {
  dense(s, t, s->tmp_y2);
  unscale(s, s->tmp_y2);
  double delta, rate;
  gap(s, s->xs, j, &delta, &rate);
  s->flags[j] = 0.0; s->armed[j] = 0;
  s->n_events++;
  if (s->open_phase[j] < 0) return;
  double *row = s->phases + s->open_phase[j] * PH_FIELDS;
  row[PH_T_OFF] = t; row[PH_V_OFF] = -rate;
  phase_quadratures(s, row, s->tmp_y2, j, 1.0);
  s->open_phase[j] = -1;
}

static void note_peak(jp_sim *s, int j, int column, int time_column, double value, double t) {
  if (s->open_phase[j] < 0) return;
  double *row = s->phases + s->open_phase[j] * PH_FIELDS;
  if (value > row[column]) {
    row[column] = value; row[time_column] = t;
    if (column == PH_F_PEAK && s->c.ns) sens_peak(s, j, t);
  }
}

/* Samples of one step: its start, INTERIOR points and its end. */
#define NS (INTERIOR + 2)
#define MAX_JOINTS 64
/* A sampled local maximum of the force this far (relative) below the phase's peak so far
 * cannot beat it (the force is resolved by the steps), so it is not refined. */
#define PEAK_MARGIN 1e-2

/* Normal force of every joint at time t on the dense output, into s->c_out (f_n's part). */
static void forces_at(jp_sim *s, double t) {
  dense_first(s, t, s->tmp_y, s->c.nx);
  unscale(s, s->tmp_y);
  normal_of(s, s->xs);
}

/* Normal force of joint j at time t on the dense output. */
static double normal_force_at(jp_sim *s, int j, double t) {
  forces_at(s, t);
  return s->c_out[3 * s->c.nc + j];
}

/* The largest normal force of joint j in [a, b]: the force is unimodal there (the samples
 * bracket its peak), and Brent's method (parabolic interpolation through the best three
 * points, a golden-section step wherever the parabola would not shrink the bracket fast
 * enough) locates it on the dense output. It stops when the peak's time is known to within
 * 1e-9 of the bracket (or round-off): the value is flat in time there, fixed to round-off.
 * Brent, "Algorithms for Minimization without Derivatives" (1973), ch. 5, on -F. */
static double peak_force(jp_sim *s, int j, double a, double b, double *t_peak) {
  const double golden = 0.5 * (3.0 - sqrt(5.0));
  const double eps = 2.220446049250313e-16;
  /* bracket at the end: b - a <= 4 tol, the golden search's stopping width */
  double tol = 0.25 * fmax(1e-9 * (b - a), 8 * eps * fmax(fabs(a), fabs(b)));
  double x = a + golden * (b - a), w = x, v = x;
  double fx = -normal_force_at(s, j, x), fw = fx, fv = fx;
  double d = 0.0, e = 0.0;
  for (int it = 0; it < 120; ++it) {
    double xm = 0.5 * (a + b), tol2 = 2.0 * tol;
    if (fabs(x - xm) <= tol2 - 0.5 * (b - a)) break;
    int parabolic = 0;
    if (fabs(e) > tol) {
      double r = (x - w) * (fx - fv), q = (x - v) * (fx - fw), pn = (x - v) * q - (x - w) * r;
      q = 2.0 * (q - r);
      if (q > 0.0) pn = -pn;
      q = fabs(q);
      double e_before = e;
      e = d;
      /* the parabola's vertex, if it lies inside the bracket and the step is less than half
       * the one before last (else the golden step) */
      if (fabs(pn) < fabs(0.5 * q * e_before) && pn > q * (a - x) && pn < q * (b - x)) {
        d = pn / q;
        double u = x + d;
        if (u - a < tol2 || b - u < tol2) d = x < xm ? tol : -tol;
        parabolic = 1;
      }
    }
    if (!parabolic) { e = x >= xm ? a - x : b - x; d = golden * e; }
    double u = fabs(d) >= tol ? x + d : x + (d > 0 ? tol : -tol);
    double fu = -normal_force_at(s, j, u);
    if (fu <= fx) {
      if (u >= x) a = x; else b = x;
      v = w; fv = fw; w = x; fw = fx; x = u; fx = fu;
    } else {
      if (u < x) a = u; else b = u;
      if (fu <= fw || w == x) { v = w; fv = fw; w = u; fw = fu; }
      else if (fu <= fv || v == x || v == w) { v = u; fv = fu; }
    }
  }
  *t_peak = x;
  return -fx;
}

/* A step redone to land on an onset ends within the integration error of the located root
 * (the root came from the dense output, the landing from a new step): a gap this close to zero
 * there, or at the start of a step, is the onset. A fraction of the local error tolerance. */
static double landing_gap(const jp_sim *s, int j) {
  return 0.1 * (s->c.atol + s->c.rtol) * s->c.clearance[j];
}

/* Scan the last step for events. Returns 0 when the step stands (events recorded), 1 when an
 * onset inside it needs the step redone up to *t_cut (nothing recorded), 3 when the onset is at
 * its very start (the step is redone from there with the captured speed). */
static int scan_events(jp_sim *s, double *t_cut, int *cut_joint) {
  const jp_config *c = &s->c;
  int nc = c->nc;
  if (!nc) return 0;
  double ts[NS], dl[NS][MAX_JOINTS], rt[NS][MAX_JOINTS];
  double t0 = s->t - s->h;
  int nx = c->nx;
  /* the state part at each sample, kept (unscaled) for the force samples of pass 2 */
  for (int k = 0; k < NS; ++k) {
    double *xk = s->samples + (size_t)k * nx;
    ts[k] = k == NS - 1 ? s->t : t0 + s->h * k / (NS - 1);
    dense_first(s, ts[k], s->tmp_y, nx);
    for (int i = 0; i < nx; ++i) xk[i] = s->tmp_y[i] * c->scale[i];
    for (int j = 0; j < nc; ++j) gap(s, xk, j, &dl[k][j], &rt[k][j]);
  }
  double landing = 1e-6 * s->h + 4 * 2.220446049250313e-16 * fabs(s->t);
  /* Pass 1: the earliest onset inside the step that is not at its end. */
  double earliest = INFINITY; int who = -1;
  for (int j = 0; j < nc; ++j) {
    int flag = s->flags[j] > 0.5, armed = s->armed[j];
    double zero_gap = landing_gap(s, j);
    for (int k = 1; k < NS; ++k) {
      if (flag) {
        if (dl[k][j] > 0) armed = 1;
        if (dl[k][j] < 0 && (armed || dl[k][j] < -c->atol * c->clearance[j])) flag = 0;
      } else if (dl[k][j] > 0 && k == 1 && dl[0][j] > -zero_gap) {
        if (t0 < earliest) { earliest = t0; who = j; } /* touching at the start */
        break;
      } else if (dl[k][j] > 0) {
        double b = locate(s, EV_DELTA, j, ts[k - 1], dl[k - 1][j], ts[k], dl[k][j], NULL);
        if (s->t - b > landing && b < earliest) { earliest = b; who = j; }
        break;
      }
    }
  }
  if (who >= 0) {
    *t_cut = earliest; *cut_joint = who;
    return earliest - t0 <= landing ? 3 : 1;
  }
  /* Pass 2: record everything. Forces are sampled only while a joint is in contact. The
   * step's ends need no new evaluation: its end is the state the quadrature rates were taken
   * at (fn_quad), its start the end of the step before (fn_carry), each equal to round-off
   * to the dense output there and valid while no onset has changed an impact speed since. */
  int any = 0; /* forces to sample: a joint in contact, and peaks asked for */
  for (int j = 0; j < nc && c->peaks; ++j) any |= s->flags[j] > 0.5;
  double fn[NS][MAX_JOINTS];
  long gen = s->v_gen;
  if (any)
    for (int k = 0; k < NS; ++k) {
      const double *known = NULL;
      if (k == 0 && s->fn_carry_t == s->t_old && s->fn_carry_gen == gen) known = s->fn_carry;
      if (k == NS - 1 && s->fn_quad_t == s->t && s->fn_quad_gen == gen) known = s->fn_quad;
      if (!known) {
        normal_of(s, s->samples + (size_t)k * nx);
        known = s->c_out + 3 * nc;
      }
      for (int j = 0; j < nc; ++j) fn[k][j] = known[j];
    }
  if (any) {
    for (int j = 0; j < nc; ++j) s->fn_carry[j] = fn[NS - 1][j];
    s->fn_carry_t = s->t; s->fn_carry_gen = gen;
  } else {
    s->fn_carry_t = NAN;
  }
  for (int j = 0; j < nc; ++j) {
    int was_in_contact = s->flags[j] > 0.5;
    int k_end = NS - 1; /* last sample of the contact inside this step */
    for (int k = 1; k < NS; ++k) {
      if (s->flags[j] < 0.5) {
        /* an onset at the end of the step: the step has landed on it (to round-off) */
        if (dl[k][j] > 0 || (k == NS - 1 && s->t >= s->landing_target &&
                             dl[k][j] > -landing_gap(s, j))) {
          memcpy(s->tmp_y2, s->D, s->N * sizeof(double));
          onset(s, j, ts[k], s->tmp_y2, 1);
        }
        continue;
      }
      if (dl[k][j] > 0) s->armed[j] = 1;
      if (rt[k - 1][j] > 0 && rt[k][j] <= 0) {
        double tm = locate(s, EV_RATE, j, ts[k - 1], rt[k - 1][j], ts[k], rt[k][j], NULL);
        note_peak(s, j, PH_D_MAX, PH_T_D, event_value(s, EV_DELTA, j, tm), tm);
      }
      if (dl[k][j] < 0 && (s->armed[j] || dl[k][j] < -c->atol * c->clearance[j])) {
        double tsep = locate(s, EV_DELTA, j, ts[k - 1], dl[k - 1][j], ts[k], dl[k][j], NULL);
        k_end = k;
        /* the force peak of this last stretch, before the phase closes */
        if (was_in_contact && c->peaks) {
          int km = 0;
          for (int q = 1; q < k; ++q) if (fn[q][j] > fn[km][j]) km = q;
          if (km > 0) {
            double tp, fp = peak_force(s, j, ts[km - 1], ts[km + 1] < tsep ? ts[km + 1] : tsep, &tp);
            note_peak(s, j, PH_F_PEAK, PH_T_F, fp, tp);
          }
        }
        separation(s, j, tsep);
        break;
      }
      note_peak(s, j, PH_D_MAX, PH_T_D, dl[k][j], ts[k]);
    }
    int rising = s->rising[j];
    if (any) s->rising[j] = fn[NS - 1][j] > fn[NS - 2][j];
    if (!c->peaks || !was_in_contact || k_end != NS - 1 || s->flags[j] < 0.5) continue;
    /* the force peak inside the step (or at its start, continuing the previous step's rise);
     * only a local maximum that can beat the phase's peak so far is refined */
    int km = 0;
    for (int q = 1; q < NS; ++q) if (fn[q][j] > fn[km][j]) km = q;
    if (km == NS - 1) { note_peak(s, j, PH_F_PEAK, PH_T_F, fn[km][j], ts[km]); continue; }
    if (km == 0 && !rising) continue;
    if (fn[km][j] < (1 - PEAK_MARGIN) * s->phases[s->open_phase[j] * PH_FIELDS + PH_F_PEAK])
      continue;
    double a = km > 0 ? ts[km - 1] : ts[0] - 0.25 * s->h;
    double tp, fp = peak_force(s, j, a, ts[km + 1], &tp);
    note_peak(s, j, PH_F_PEAK, PH_T_F, fmax(fp, fn[km][j]), fp >= fn[km][j] ? tp : ts[km]);
  }
  return 0;
}

/* ---- wear ------------------------------------------------------------------------------------ */

#define JP_PI 3.14159265358979323846

/* Outputs of the generated wear function, per joint (see jointplay.derive.wear). */
enum { WO_BEARING_ANGLE, WO_JOURNAL_ANGLE, WO_RATE, WO_BEARING_HALF, WO_JOURNAL_HALF,
       WO_BEARING_AREA, WO_JOURNAL_AREA, WO_BEARING_SPEED, WO_JOURNAL_SPEED, WO_FIELDS };
/* A step is cut into at most this many pieces for the wear quadrature. */
#define WEAR_MAX_PIECES 100000

/* Share of Hertz's elliptical pressure p ~ (1 - u^2)^(1/2) on u in [-1, x]. */
static double ellipse_share(double x) {
  if (x <= -1.0) return 0.0;
  if (x >= 1.0) return 1.0;
  return 0.5 + (x * sqrt(1.0 - x * x) + asin(x)) / JP_PI;
}

/* Spread a worn volume over the bins of one surface: elliptically over the contact arc
 * [angle - half, angle + half], each bin's share integrated exactly, as the bin's mean depth
 * (volume share over the bin's surface, area * bin width). */
static void deposit(double *bins, int nb, double angle, double half, double volume,
                    double area) {
  const double two_pi = 2.0 * JP_PI, width = two_pi / nb;
  double a = fmod(angle, two_pi);
  if (a < 0) a += two_pi;
  double scale = volume / (area * width);
  if (!(half > 1e-9 * width)) { /* no width (no force) or not finite: one bin */
    int k = (int)(a / width);
    bins[k < nb ? k : nb - 1] += scale;
    return;
  }
  if (half > JP_PI) half = JP_PI; /* the contact cannot wrap past itself */
  int k0 = (int)floor((a - half) / width), k1 = (int)floor((a + half) / width);
  for (int k = k0; k <= k1; ++k) {
    double lo = fmax(k * width, a - half), hi = fmin((k + 1) * width, a + half);
    double share = ellipse_share((hi - a) / half) - ellipse_share((lo - a) / half);
    bins[((k % nb) + nb) % nb] += scale * share;
  }
}

static const double GL_NODE[3] = {-0.7745966692414834, 0.0, 0.7745966692414834};
static const double GL_WEIGHT[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};

/* The model's wear outputs at time t on the dense output of the last step. */
static void wear_at(jp_sim *s, double t) {
  const jp_config *c = &s->c;
  dense(s, t, s->tmp_y);
  unscale(s, s->tmp_y);
  s->arg[0] = s->xs; s->arg[1] = c->p; s->arg[2] = s->v_imp;
  for (int k = 0; k < WO_FIELDS; ++k) s->res[k] = s->wear_out + k * c->nc;
  call(s, &c->wear);
}

/* Wear over the step that just stood, [t - h, t]: three-point Gauss-Legendre in time (exact
 * for polynomials of degree 5) on the dense output, over pieces of the step short enough
 * that the contact moves less than half a bin on either surface (the depth in one bin is not
 * smooth in time while the contact passes over it); the pieces' count comes from the contact
 * angles' rates at the step's own Gauss nodes, where any joint wears. */
static void wear_step(jp_sim *s) {
  const jp_config *c = &s->c;
  int nc = c->nc, nb = c->wear_bins;
  double t0 = s->t - s->h, width = 2.0 * JP_PI / nb, travel = 0.0;
  int wearing = 0;
  for (int g = 0; g < 3; ++g) {
    wear_at(s, t0 + 0.5 * s->h * (1.0 + GL_NODE[g]));
    for (int j = 0; j < nc; ++j) {
      if (!(s->wear_out[WO_RATE * nc + j] > 0)) continue;
      wearing = 1;
      travel = fmax(travel, fabs(s->wear_out[WO_BEARING_SPEED * nc + j]) * s->h);
      travel = fmax(travel, fabs(s->wear_out[WO_JOURNAL_SPEED * nc + j]) * s->h);
    }
  }
  if (!wearing) return;
  double wanted = ceil(travel / (0.5 * width));
  long pieces = wanted < 1 ? 1 : wanted > WEAR_MAX_PIECES ? WEAR_MAX_PIECES : (long)wanted;
  double piece = s->h / pieces, half = 0.5 * piece;
  for (long m = 0; m < pieces; ++m) {
    for (int g = 0; g < 3; ++g) {
      wear_at(s, t0 + m * piece + half * (1.0 + GL_NODE[g]));
      const double *o = s->wear_out;
      for (int j = 0; j < nc; ++j) {
        double volume = GL_WEIGHT[g] * half * o[WO_RATE * nc + j];
        if (!(volume > 0)) continue;
        s->wear_volume[j] += volume;
        deposit(s->wear_depth + (size_t)j * nb, nb, o[WO_BEARING_ANGLE * nc + j],
                o[WO_BEARING_HALF * nc + j], volume, o[WO_BEARING_AREA * nc + j]);
        deposit(s->wear_depth + (size_t)(nc + j) * nb, nb, o[WO_JOURNAL_ANGLE * nc + j],
                o[WO_JOURNAL_HALF * nc + j], volume, o[WO_JOURNAL_AREA * nc + j]);
      }
    }
  }
}

/* ---- public interface ------------------------------------------------------------------------ */

/* Whether driven joints a and b have the same torque definition (the same program, or the
 * same table): a scene that drives every joint alike evaluates it once per time. */
static int same_torque(const jp_config *c, int a, int b) {
  if (c->torque_kind[a] != c->torque_kind[b] || c->torque_len[a] != c->torque_len[b]) return 0;
  int n = c->torque_len[a], sa = c->torque_start[a], sb = c->torque_start[b];
  if (c->torque_kind[a] == 0)
    return memcmp(c->ops + sa, c->ops + sb, n * sizeof(int)) == 0
           && memcmp(c->consts + sa, c->consts + sb, n * sizeof(double)) == 0;
  return memcmp(c->table_t + sa, c->table_t + sb, n * sizeof(double)) == 0
         && memcmp(c->table_v + sa, c->table_v + sb, n * sizeof(double)) == 0;
}

void jp_free(jp_sim *s);

jp_sim *jp_create(const jp_config *config) {
  static int constants_ready = 0;
  if (!constants_ready) { bdf_constants(); constants_ready = 1; }
  jp_sim *s = calloc(1, sizeof(jp_sim));
  if (!s) return NULL;
  s->c = *config;
  s->tau_t = NAN;
  const jp_config *c = &s->c;
  int nx = c->nx, nc = c->nc;
  s->nquad = 1 + 3 * nc;
  s->sens_col = nx + s->nquad;
  s->sens_record = sens_record_size(c);
  s->N = nx + s->nquad + c->ns * nx;
  int N = s->N;
  size_t rows = MAX_ORDER + 3;
  s->D = calloc(rows * N, sizeof(double));
  s->D_save = calloc(rows * N, sizeof(double));
  s->work_n = calloc(rows * N, sizeof(double));
  s->J = calloc((size_t)nx * nx, sizeof(double));
  s->LU = calloc((size_t)nx * nx, sizeof(double));
  s->LT = calloc((size_t)nx * nx, sizeof(double));
  s->JqT = calloc((size_t)nx * nx / 4 + 1, sizeof(double));
  s->piv = calloc(nx, sizeof(int));
  s->rhs_u = calloc(nx / 2 + 1, sizeof(double));
  double **vecs[] = {&s->y_pred, &s->psi, &s->d, &s->y_new, &s->f_buf, &s->dy, &s->scal,
                     &s->err, &s->tmp_y, &s->tmp_y2};
  for (size_t k = 0; k < sizeof(vecs) / sizeof(vecs[0]); ++k) *vecs[k] = calloc(N, sizeof(double));
  s->xs = calloc(nx, sizeof(double));
  s->xdot = calloc(nx, sizeof(double));
  s->tau = calloc(c->ntau + 1, sizeof(double));
  s->u_hold = calloc(c->ntau + 1, sizeof(double));
  s->tau_scene = calloc(c->ntau + 1, sizeof(double));
  s->torque_same = calloc(c->ntau + 1, sizeof(int));
  for (int k = 0; k < c->ntau && s->torque_same; ++k) {
    s->torque_same[k] = -1;
    for (int m = 0; m < k && s->torque_same[k] < 0; ++m)
      if (s->torque_same[m] < 0 && same_torque(c, m, k)) s->torque_same[k] = m;
  }
  s->v_imp = calloc(nc + 1, sizeof(double));
  s->flags = calloc(nc + 1, sizeof(double));
  s->armed = calloc(nc + 1, sizeof(int));
  s->rising = calloc(nc + 1, sizeof(int));
  s->open_phase = calloc(nc + 1, sizeof(long));
  s->c_out = calloc(8 * (nc + 1), sizeof(double));
  s->g_out = calloc(4 * (nc + 1), sizeof(double));
  s->samples = calloc((size_t)NS * nx + 1, sizeof(double));
  s->fn_quad = calloc(nc + 1, sizeof(double));
  s->fn_carry = calloc(nc + 1, sizeof(double));
  s->fn_quad_t = s->fn_carry_t = NAN;
  jp_int sz_arg = 8, sz_res = 8, sz_iw = 0, sz_w = 0;
  const jp_function *fns[9] = {&c->f, &c->jac, &c->contact, &c->wear, &c->normal,
                               &c->jac_in, &c->dir_in, &c->gap_fn, &c->power_fn};
  for (int k = 0; k < 9; ++k) {
    if (!fns[k]->eval) continue;
    if (fns[k]->sz_arg > sz_arg) sz_arg = fns[k]->sz_arg;
    if (fns[k]->sz_res > sz_res) sz_res = fns[k]->sz_res;
    if (fns[k]->sz_iw > sz_iw) sz_iw = fns[k]->sz_iw;
    if (fns[k]->sz_w > sz_w) sz_w = fns[k]->sz_w;
  }
  s->arg = calloc(sz_arg, sizeof(double *));
  s->res = calloc(sz_res, sizeof(double *));
  s->iw = calloc(sz_iw + 1, sizeof(jp_int));
  s->w = calloc(sz_w + 1, sizeof(double));
  jp_int nnz = c->jac.sparsity_out0[2 + c->jac.sparsity_out0[1]];
  s->jac_sparse = calloc(nnz + 1, sizeof(double));
  if (!s->D || !s->D_save || !s->work_n || !s->J || !s->LU || !s->LT || !s->JqT || !s->piv ||
      !s->rhs_u || !s->tmp_y2 ||
      !s->xs || !s->xdot || !s->tau || !s->u_hold || !s->tau_scene || !s->torque_same ||
      !s->v_imp || !s->flags || !s->armed || !s->rising ||
      !s->open_phase || !s->c_out || !s->g_out || !s->samples || !s->fn_quad || !s->fn_carry || !s->arg ||
      !s->res || !s->iw || !s->w || !s->jac_sparse) {
    jp_free(s);
    return NULL;
  }
  for (int j = 0; j < nc; ++j) s->open_phase[j] = -1;
  if (c->ns) {
    size_t nxx = (size_t)nx * nx;
    s->Js = calloc(nxx, sizeof(double)); s->LUs = calloc(nxx, sizeof(double));
    s->LTs = calloc(nxx, sizeof(double)); s->pivs = calloc(nx, sizeof(int));
    s->bz = calloc((size_t)c->ns * nx, sizeof(double));
    s->fp_sparse = calloc(c->sp_p[2 + c->sp_p[1]] + 1, sizeof(double));
    s->fv_sparse = calloc((nc ? c->sp_v[2 + c->sp_v[1]] : 0) + 1, sizeof(double));
    s->v_sens = calloc((size_t)nc * c->ns + 1, sizeof(double));
    s->sens_tmp = calloc(N, sizeof(double));
    s->f_minus = calloc(nx, sizeof(double)); s->f_plus = calloc(nx, sizeof(double));
    int k = c->dir_in.eval ? c->dir_k : 0;
    s->seeds = calloc((size_t)(c->np + nc) * k + 1, sizeof(double));
    s->dir_out = calloc((size_t)nx * k + 1, sizeof(double));
    if (!s->Js || !s->LUs || !s->LTs || !s->pivs || !s->bz || !s->fp_sparse ||
        !s->fv_sparse || !s->v_sens || !s->sens_tmp || !s->f_minus || !s->f_plus ||
        !s->seeds || !s->dir_out || !c->jac_in.eval || (c->dir_in.eval && k < 1)) {
      jp_free(s);
      return NULL;
    }
  }
  if (c->wear.eval) {
    s->wear_out = calloc((size_t)WO_FIELDS * nc + 1, sizeof(double));
    s->wear_volume = calloc(nc + 1, sizeof(double));
    s->wear_depth = calloc((size_t)2 * nc * c->wear_bins + 1, sizeof(double));
    if (!s->wear_out || !s->wear_volume || !s->wear_depth || c->wear_bins < 1) {
      jp_free(s);
      return NULL;
    }
  }
  return s;
}

void jp_free(jp_sim *s) {
  if (!s) return;
  void *ptrs[] = {s->D, s->D_save, s->work_n, s->J, s->LU, s->LT, s->JqT, s->piv, s->rhs_u,
                  s->y_pred,
                  s->psi, s->d, s->y_new, s->f_buf, s->dy, s->scal, s->err, s->tmp_y, s->tmp_y2, s->xs,
                  s->xdot, s->tau, s->u_hold, s->tau_scene, s->torque_same, s->v_imp, s->flags, s->g_out,
                  s->armed, s->rising, s->open_phase,
                  s->c_out, s->samples, s->fn_quad, s->fn_carry, s->arg, s->res, s->iw, s->w, s->jac_sparse, s->phases,
                  s->wear_out, s->wear_volume, s->wear_depth, s->Js, s->LUs, s->LTs,
                  s->pivs, s->bz, s->fp_sparse, s->fv_sparse, s->v_sens, s->sens_tmp,
                  s->f_minus, s->f_plus, s->seeds, s->dir_out, s->phase_sens};
  for (size_t k = 0; k < sizeof(ptrs) / sizeof(ptrs[0]); ++k) free(ptrs[k]);
  free(s);
}

/* Put the run at (t0, x0) (unscaled state), quadratures zero, no phases; a contact already
 * present at t0 opens a phase there. */
int jp_reset(jp_sim *s, double t0, const double *x0) {
  const jp_config *c = &s->c;
  for (int i = 0; i < c->nx; ++i) s->D[i] = x0[i] / c->scale[i];
  for (int i = 0; i < s->nquad; ++i) s->D[c->nx + i] = 0.0;
  s->t = t0; s->started = 0; s->status = JP_OK; s->tau_t = NAN;
  s->fn_quad_t = s->fn_carry_t = NAN; s->n_phases = 0; s->landing_target = INFINITY;
  s->order_cap = c->max_order; s->cap_steps = 0; s->window_steps = 0; s->recent_failures = 0;
  for (int j = 0; j < c->nc; ++j) {
    s->flags[j] = 0.0; s->v_imp[j] = 0.0; s->armed[j] = 0; s->open_phase[j] = -1;
  }
  s->n_steps = s->n_rhs = s->n_jac = s->n_lu = s->n_err_fail = s->n_newton_fail = 0;
  s->n_events = s->n_onsets = 0; s->n_lu_reduced = 0;
  const char *newton = getenv("JOINTPLAY_NEWTON");
  s->newton = newton == NULL ? c->newton
              : strcmp(newton, "full") == 0 ? JP_NEWTON_FULL
              : strcmp(newton, "reduced") == 0 ? JP_NEWTON_REDUCED : JP_NEWTON_AUTO;
  if (c->wear.eval) {
    memset(s->wear_volume, 0, c->nc * sizeof(double));
    memset(s->wear_depth, 0, (size_t)2 * c->nc * c->wear_bins * sizeof(double));
  }
  /* the initial sensitivities, and no impact speed's derivative yet */
  for (int q = 0; q < c->ns; ++q)
    for (int i = 0; i < c->nx; ++i)
      s->D[s->sens_col + q * c->nx + i] = c->s0[q * c->nx + i] / c->scale[i];
  if (c->ns) memset(s->v_sens, 0, (size_t)c->nc * c->ns * sizeof(double));
  s->n_sens_jac = 0;
  memcpy(s->tmp_y2, s->D, s->N * sizeof(double));
  for (int j = 0; j < c->nc; ++j) {
    double delta;
    gap(s, x0, j, &delta, NULL);
    if (delta > 0) onset(s, j, t0, s->tmp_y2, 0);
  }
  return s->status;
}

/* Torques added to the scene's and held from now on; a change restarts the method (the
 * right-hand side jumps). */
void jp_hold(jp_sim *s, const double *u) {
  int changed = 0;
  for (int k = 0; k < s->c.ntau; ++k) if (s->u_hold[k] != u[k]) { s->u_hold[k] = u[k]; changed = 1; }
  if (changed) s->started = 0, s->tau_t = NAN;
}

/* Integrate to t_end, writing outputs at the n_out times t_out (increasing, in (t, t_end]):
 * y_out rows of nx + nquad values (state unscaled, then the cumulative quadratures), v_out rows
 * of nc captured approach speeds. Returns a status (JP_OK on success). */
int jp_integrate(jp_sim *s, double t_end, long n_out, const double *t_out, double *y_out,
                 double *v_out) {
  const jp_config *c = &s->c;
  int N = s->N, nx = c->nx;
  struct sigaction action, previous;
  memset(&action, 0, sizeof(action));
  action.sa_handler = jp_on_sigint;
  sigemptyset(&action.sa_mask);
  jp_interrupted = 0;
  sigaction(SIGINT, &action, &previous);
  long next = 0, steps_since_output = 0, events_since_output = 0;
  double bound = t_end;
  s->status = JP_OK;
  if (!s->started) {
    memcpy(s->tmp_y, s->D, N * sizeof(double));
    double *z0 = malloc(N * sizeof(double));
    if (!z0) { s->status = JP_NO_MEMORY; goto done; }
    memcpy(z0, s->tmp_y, N * sizeof(double));
    int rc = bdf_start(s, s->t, z0, z0 + nx, t_end);
    free(z0);
    if (rc) goto done;
  }
  while (s->t < t_end) {
    if (jp_interrupted) { s->status = JP_INTERRUPTED; s->fail_t = s->t; break; }
    if (bdf_step(s, bound)) break;
    double t_cut = 0.0; int cut_joint = -1;
    int ev = scan_events(s, &t_cut, &cut_joint);
    if (s->status) break;
    if (ev == 1 || ev == 3) {
      /* redo the step: to land on the onset, or from its start with the captured speed */
      memcpy(s->D, s->D_save, (size_t)(s->order_old + 3) * N * sizeof(double));
      s->t = s->t_old; s->h_abs = s->h_abs_old; s->order = s->order_old;
      s->n_equal_steps = s->n_equal_old; s->have_lu = 0; s->n_steps--;
      if (ev == 1) {
        bound = t_cut; s->landing_target = t_cut;
      } else {
        memcpy(s->tmp_y2, s->D, N * sizeof(double));
        onset(s, cut_joint, s->t, s->tmp_y2, 1);
        if (s->status) break;
      }
      if (++events_since_output > c->max_events) {
        s->status = JP_CHATTER; s->fail_t = s->t; s->fail_joint = cut_joint; break;
      }
      continue;
    }
    if (c->wear.eval) wear_step(s);
    if (s->t >= bound) { bound = t_end; s->landing_target = INFINITY; }
    while (next < n_out && t_out[next] <= s->t) {
      dense(s, t_out[next], s->tmp_y);
      double *row = y_out + next * N;
      for (int i = 0; i < nx; ++i) row[i] = s->tmp_y[i] * c->scale[i];
      for (int i = nx; i < N; ++i) row[i] = s->tmp_y[i];
      if (t_out[next] == s->t) for (int i = 0; i < N; ++i) row[i] = s->D[i] * (i < nx ? c->scale[i] : 1.0);
      for (int j = 0; j < c->nc; ++j) v_out[next * c->nc + j] = s->v_imp[j];
      next++;
      steps_since_output = 0; events_since_output = 0;
    }
    if (++steps_since_output > c->max_steps) {
      s->status = JP_TOO_MUCH_WORK; s->fail_t = s->t; break;
    }
    if (!all_finite(N, s->D)) { s->status = JP_NONFINITE; s->fail_t = s->t; break; }
    bdf_adapt(s);
  }
done:
  sigaction(SIGINT, &previous, NULL);
  return s->status;
}

/* The current (scaled) point: state unscaled then quadratures, N values. */
void jp_current(const jp_sim *s, double *y) {
  for (int i = 0; i < s->N; ++i) y[i] = s->D[i] * (i < s->c.nx ? s->c.scale[i] : 1.0);
}

long jp_n_phases(const jp_sim *s) { return s->n_phases; }
int jp_phase_fields(void) { return PH_FIELDS; }
void jp_phases(const jp_sim *s, double *out) {
  memcpy(out, s->phases, (size_t)s->n_phases * PH_FIELDS * sizeof(double));
}
void jp_flags(const jp_sim *s, double *flags, double *v_imp) {
  for (int j = 0; j < s->c.nc; ++j) { flags[j] = s->flags[j]; v_imp[j] = s->v_imp[j]; }
}
void jp_stats(const jp_sim *s, long *out) {
  out[0] = s->n_steps; out[1] = s->n_rhs; out[2] = s->n_jac; out[3] = s->n_lu;
  out[4] = s->n_err_fail; out[5] = s->n_newton_fail; out[6] = s->n_events; out[7] = s->n_onsets;
  out[8] = s->n_lu_reduced; out[9] = s->n_sens_jac;
}
/* The phases' sensitivity records (see sens_record_size), n_phases x record. */
int jp_sens_record(const jp_sim *s) { return s->sens_record; }
void jp_phase_sens(const jp_sim *s, double *out) {
  if (s->c.ns)
    memcpy(out, s->phase_sens, (size_t)s->n_phases * s->sens_record * sizeof(double));
}
void jp_failure(const jp_sim *s, double *t, double *h, int *joint) {
  *t = s->fail_t; *h = s->fail_h; *joint = s->fail_joint;
}
int jp_n_state(const jp_sim *s) { return s->N; }

/* Wear so far: volume (nc), then depth (2 x nc x bins: bearings, then journals). */
void jp_wear(const jp_sim *s, double *volume, double *depth) {
  if (!s->c.wear.eval) return;
  memcpy(volume, s->wear_volume, s->c.nc * sizeof(double));
  memcpy(depth, s->wear_depth, (size_t)2 * s->c.nc * s->c.wear_bins * sizeof(double));
}

/* Evaluate a generated function on `count` samples: input i of sample k at in[i] + k *
 * in_stride[i] (stride 0: the same for every sample), output likewise. For the derived
 * outputs of a run (accelerations, tip, energies, contact forces) without a Python loop. */
int jp_map(const jp_function *fn, long count, const double *const *in, const long *in_stride,
           double *const *out, const long *out_stride) {
  const double **arg = calloc(fn->sz_arg + 1, sizeof(double *));
  double **res = calloc(fn->sz_res + 1, sizeof(double *));
  jp_int *iw = calloc(fn->sz_iw + 1, sizeof(jp_int));
  double *w = calloc(fn->sz_w + 1, sizeof(double));
  int rc = 0;
  if (!arg || !res || !iw || !w) rc = JP_NO_MEMORY;
  for (long k = 0; k < count && !rc; ++k) {
    for (jp_int i = 0; i < fn->n_in; ++i) arg[i] = in[i] ? in[i] + k * in_stride[i] : NULL;
    for (jp_int i = 0; i < fn->n_out; ++i) res[i] = out[i] ? out[i] + k * out_stride[i] : NULL;
    rc = fn->eval(arg, res, iw, w, 0);
  }
  free(arg); free(res); free(iw); free(w);
  return rc;
}
