/*
 * Compiled one-case Newton iteration of ballrace.analytic.loaddist (optional).
 *
 * The same iteration as loaddist._newton_one (either moment arm): per ball the
 * groove-centre offsets (x, z), the approach s - A without cancellation, K_n(beta) from
 * the Chebyshev table of ln K_n in tau = 2 cos(beta) - 1, the load Q = K_n delta^1.5,
 * the resultant and the analytic Jacobian (scaled: moments and tilts by R_i); the scaled
 * Newton step with the Levenberg floor, the trust radius, the line minimiser of the
 * linearised potential from the touching reference, the Armijo search on the
 * frozen-stiffness potential (groove arm) or on the residual norm (contact arm), the
 * round-off floor.  See loaddist._one_case and
 * loaddist._newton_one for the formulas.
 *
 * It only proposes a displacement: loaddist evaluates the NumPy kernel there, checks the
 * equilibrium and goes on with its own Newton iteration when the residual is above rtol.
 * Whatever this code cannot handle (a ball with cos(beta) < 0, a singular or non-descent
 * step, no convergence) returns a status and loaddist solves the case itself.
 *
 * newton_one(pack, F, fixed, u0, rtol, max_iter, seat, contact) -> (status, iterations, u)
 *   pack  : float64 buffer [Z, ntab, R_i, A, x0, z0, g0, K_seat, d_e/(2 R_i), D/(2 R_i),
 *           cos psi (Z),
 *           sin psi (Z), table (ntab x 2: ln K_n and -2 d ln K_n / d tau coefficients)]
 *   F     : 5 floats, the applied loads, 0 on imposed DOFs [N, N m]
 *   fixed : 5 floats, 1.0 for imposed DOFs
 *   u0    : 5 floats, the start [m, rad]
 *   seat  : the start is the touching reference (u0 = 0, no ball loaded)
 *   contact: the moment arm of the ball thrust is the contact radius (d_e - D cos b)/2
 *           (Ricci 2009 eq. 29) instead of the groove radius R_i
 *   status: 0 converged, 1 not converged within max_iter, 2 case left to loaddist
 */
#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <math.h>
#include <float.h>
#include <stdlib.h>
#include <string.h>

#define MAXTAB 64

typedef struct {
    int Z, ntab, contact;
    double Ri, A, x0, z0, g0, Kseat, rho0, kD;
    const double *cp, *sp, *tab;
} Geo;

typedef struct {
    double F[5], J[25];        /* scaled resultant and Jacobian */
    double *delta, *Kn, *Q;    /* per ball (Z) */
    double qmax, dmax;
} State;

/* ln K_n and d ln K_n / d beta (table column 1 holds -2 d/dtau): Clenshaw's recurrence */
static void kn_table(const Geo *g, double c, double sn, double *Kn, double *dlnK)
{
    double tau = 2.0 * c - 1.0, t2 = 2.0 * tau;
    double b1 = 0.0, b2 = 0.0, d1 = 0.0, d2 = 0.0, tmp;
    int k;
    for (k = g->ntab - 1; k >= 1; k--) {
        tmp = t2 * b1 - b2 + g->tab[2 * k];
        b2 = b1;
        b1 = tmp;
        tmp = t2 * d1 - d2 + g->tab[2 * k + 1];
        d2 = d1;
        d1 = tmp;
    }
    *Kn = exp(tau * b1 - b2 + g->tab[0]);
    *dlnK = sn * (tau * d1 - d2 + g->tab[1]);
}

/* ball offsets of displacement u: dx = (dy cos psi + dz sin psi), dz = dx_axial + R_i(...) */
static inline void offsets(const Geo *g, const double *u, int j, double *dx, double *dz)
{
    double cp = g->cp[j], sp = g->sp[j];
    *dx = u[1] * cp + u[2] * sp;
    *dz = u[0] + u[3] * (g->Ri * sp) + u[4] * (-g->Ri * cp);
}

static inline double approach(const Geo *g, double dx, double dz, double *x, double *z,
                              double *s)
{
    *x = g->x0 + dx;
    *z = g->z0 + dz;
    *s = hypot(*x, *z);
    return (g->g0 + dx * (2.0 * g->x0 + dx) + dz * (2.0 * g->z0 + dz)) / (*s + g->A);
}

/* the state at u; 0, or 2 when a ball has cos(beta) < 0 or a value is not finite */
static int kernel(const Geo *g, const double *u, State *st)
{
    int j, a, b;
    double W[4], gx[5], gz[5];
    memset(st->F, 0, sizeof st->F);
    memset(st->J, 0, sizeof st->J);
    st->qmax = 0.0;
    st->dmax = 0.0;
    for (j = 0; j < g->Z; j++) {
        double dx, dz, x, z, s, ap, c, sn, d, Kn, dlnK, sq, Q, k15, qs, qk, fr, fa;
        offsets(g, u, j, &dx, &dz);
        ap = approach(g, dx, dz, &x, &z, &s);
        if (!(s > 0.0))
            return 2;
        c = x / s;
        sn = z / s;
        if (!(c >= 0.0))
            return 2;
        d = ap > 0.0 ? ap : 0.0;
        if (!(x > 0.0))
            d = 0.0;
        kn_table(g, c, sn, &Kn, &dlnK);
        sq = sqrt(d);
        Q = Kn * sq * d;
        k15 = 1.5 * Kn * sq;
        qs = Q / s;
        qk = qs * dlnK;
        st->delta[j] = d;
        st->Kn[j] = Kn;
        st->Q[j] = Q;
        if (Q > st->qmax)
            st->qmax = Q;
        if (d > st->dmax)
            st->dmax = d;
        fr = Q * c;
        fa = Q * sn;
        double far = fa, W2r, W3r;
        W[0] = k15 * c * c - qk * c * sn + qs * sn * sn;      /* d(Q cos b)/dx */
        W[1] = k15 * c * sn + qk * c * c - qs * c * sn;       /* d(Q cos b)/dz */
        W[2] = k15 * c * sn - qk * sn * sn - qs * c * sn;     /* d(Q sin b)/dx */
        W[3] = k15 * sn * sn + qk * c * sn + qs * c * c;      /* d(Q sin b)/dz */
        gx[0] = 0.0; gx[1] = g->cp[j]; gx[2] = g->sp[j]; gx[3] = 0.0; gx[4] = 0.0;
        gz[0] = 1.0; gz[1] = 0.0; gz[2] = 0.0; gz[3] = g->sp[j]; gz[4] = -g->cp[j];
        W2r = W[2];
        W3r = W[3];
        if (g->contact) {
            /* rows 3, 4: arm rho = r / R_i and the change of r = (d_e - D cos b)/2 with b */
            double rho = g->rho0 - g->kD * c, q3 = g->kD * qs * sn * sn;
            far = fa * rho;
            W2r = W[2] * rho - q3 * sn;
            W3r = W[3] * rho + q3 * c;
        }
        for (a = 0; a < 5; a++) {
            double fa_ = a < 3 ? fa : far, w2 = a < 3 ? W[2] : W2r, w3 = a < 3 ? W[3] : W3r;
            st->F[a] += fr * gx[a] + fa_ * gz[a];
            for (b = 0; b < 5; b++)
                st->J[5 * a + b] += W[0] * gx[a] * gx[b] + W[1] * gx[a] * gz[b]
                    + w2 * gz[a] * gx[b] + w3 * gz[a] * gz[b];
        }
    }
    for (a = 0; a < 5; a++)
        if (!isfinite(st->F[a]))
            return 2;
    return 0;
}

/* frozen-stiffness potential 0.4 sum Kf delta^2.5 - F.u at u (see loaddist._potential) */
static double potential(const Geo *g, const double *u, const double *Kf, const double *F)
{
    double e = 0.0, dx, dz, x, z, s, d;
    int j, a;
    for (j = 0; j < g->Z; j++) {
        offsets(g, u, j, &dx, &dz);
        d = approach(g, dx, dz, &x, &z, &s);
        if (x > 0.0 && d > 0.0)
            e += Kf[j] * d * d * sqrt(d);
    }
    e *= 0.4;
    for (a = 0; a < 5; a++)
        e -= F[a] * u[a];
    return e;
}

/* solve A x = b (5 x 5, row major, overwritten) by LU with partial pivoting; 0 if singular */
static int solve5(double *A, double *b, double *x)
{
    int i, j, k, p;
    double m, t;
    for (k = 0; k < 5; k++) {
        p = k;
        for (i = k + 1; i < 5; i++)
            if (fabs(A[5 * i + k]) > fabs(A[5 * p + k]))
                p = i;
        if (A[5 * p + k] == 0.0)
            return 0;
        if (p != k) {
            for (j = 0; j < 5; j++) {
                t = A[5 * k + j]; A[5 * k + j] = A[5 * p + j]; A[5 * p + j] = t;
            }
            t = b[k]; b[k] = b[p]; b[p] = t;
        }
        for (i = k + 1; i < 5; i++) {
            m = A[5 * i + k] / A[5 * k + k];
            if (m != 0.0) {
                for (j = k + 1; j < 5; j++)
                    A[5 * i + j] -= m * A[5 * k + j];
                b[i] -= m * b[k];
            }
        }
    }
    for (i = 4; i >= 0; i--) {
        t = b[i];
        for (j = i + 1; j < 5; j++)
            t -= A[5 * i + j] * x[j];
        x[i] = t / A[5 * i + i];
        if (!isfinite(x[i]))
            return 0;
    }
    return 1;
}

static double dot5(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3] + a[4] * b[4];
}

/* scaled residual R = F_s - F_ext_s (0 on imposed DOFs) and its relative size */
static double residual(const State *st, const double *Fsx, const double *fixed,
                       double Fs_ext, double *R)
{
    double e = 0.0, scale;
    int a;
    for (a = 0; a < 5; a++) {
        R[a] = fixed[a] != 0.0 ? 0.0 : st->F[a] - Fsx[a];
        if (isnan(R[a]))
            return NAN;
        if (fabs(R[a]) > e)
            e = fabs(R[a]);
    }
    scale = Fs_ext > st->qmax ? Fs_ext : st->qmax;
    if (scale < 1e-300)
        scale = 1e-300;
    return e / scale;
}

static int newton_(const Geo *g, const double *F, const double *fixed, double *u,
                   double rtol, long max_iter, int seat, long *iters, State *st, State *sn_);

/* the iteration from u (overwritten by the result); status as newton_one */
static int newton(const Geo *g, const double *F, const double *fixed, double *u,
                  double rtol, long max_iter, int seat, long *iters)
{
    State S1, S2;
    int status;
    double *work = (double *) calloc(6 * (size_t) g->Z, sizeof(double));
    if (work == NULL)
        return 2;
    S1.delta = work; S1.Kn = work + g->Z; S1.Q = work + 2 * g->Z;
    S2.delta = work + 3 * g->Z; S2.Kn = work + 4 * g->Z; S2.Q = work + 5 * g->Z;
    status = newton_(g, F, fixed, u, rtol, max_iter, seat, iters, &S1, &S2);
    free(work);
    return status;
}

static int newton_(const Geo *g, const double *F, const double *fixed, double *u,
                   double rtol, long max_iter, int seat, long *iters, State *st, State *sn_)
{
    double sc[5] = {1.0, 1.0, 1.0, g->Ri, g->Ri};
    double Fsx[5], R[5], Rn[5], Js[25], rhs[5], dS[5], du[5], unew[5], best_u[5];
    double Fs_ext = 0.0, err, en, best_err, mu, tr, size, gslope, t, phi0, ph, cap, fl, dmx,
        umx, num, den, f;
    double step_max = 0.25 * g->A, lev = 1e-6 / g->A, eps20 = 20.0 * DBL_EPSILON;
    int a, b, j, n_free = 0, local, floor_, k;
    State *tmp;
    long it = 0;
    for (a = 0; a < 5; a++) {
        Fsx[a] = F[a] / sc[a];
        if (fabs(Fsx[a]) > Fs_ext)
            Fs_ext = fabs(Fsx[a]);
        if (fixed[a] == 0.0)
            n_free++;
    }
    if (n_free < 1)
        n_free = 1;
    cap = 100.0 * rtol > 1e-9 ? 100.0 * rtol : 1e-9;
    if (seat) {                 /* touching reference: no ball loaded, no stiffness */
        memset(st->F, 0, sizeof st->F);
        memset(st->J, 0, sizeof st->J);
        st->qmax = st->dmax = 0.0;
        for (j = 0; j < g->Z; j++) {
            st->Kn[j] = g->Kseat;
            st->delta[j] = st->Q[j] = 0.0;
        }
    } else if (kernel(g, u, st))
        return 2;
    err = residual(st, Fsx, fixed, Fs_ext, R);
    best_err = err == err ? err : INFINITY;
    memcpy(best_u, u, sizeof best_u);
    while (!(err <= rtol)) {
        if (it >= max_iter) {
            if (best_err <= cap) {
                memcpy(u, best_u, sizeof best_u);
                break;
            }
            *iters = it;
            return 1;
        }
        it++;
        tr = 0.0;
        for (a = 0; a < 5; a++)
            for (b = 0; b < 5; b++) {
                Js[5 * a + b] = (fixed[a] != 0.0 || fixed[b] != 0.0) ? 0.0 : st->J[5 * a + b];
                if (a == b)
                    tr += Js[5 * a + b];
            }
        mu = 1e-12 * fabs(tr) / n_free;
        f = lev * (Fs_ext > st->qmax ? Fs_ext : st->qmax);
        if (f > mu)
            mu = f;
        for (a = 0; a < 5; a++) {
            Js[6 * a] += fixed[a] != 0.0 ? 1.0 : mu;
            rhs[a] = R[a];
        }
        if (!solve5(Js, rhs, dS))
            return 2;
        for (a = 0; a < 5; a++)
            dS[a] = -dS[a];
        if (!g->contact && !(dot5(R, dS) < 0.0))
            return 2;           /* loaddist takes the symmetric frozen-stiffness step */
        size = 0.0;
        for (a = 0; a < 5; a++)
            if (fabs(dS[a]) > size)
                size = fabs(dS[a]);
        if (seat && it == 1) {
            /* line minimiser of the linearised frozen potential from the reference */
            double s0 = hypot(g->x0, g->z0), c0 = g->x0 / s0, sn0 = g->z0 / s0, bj, dx, dz;
            for (a = 0; a < 5; a++)
                du[a] = dS[a] / sc[a];
            den = 0.0;
            for (j = 0; j < g->Z; j++) {
                offsets(g, du, j, &dx, &dz);
                bj = dx * c0 + dz * sn0;
                if (bj > 0.0)
                    den += g->Kseat * bj * bj * sqrt(bj);
            }
            num = dot5(F, du);
            if (den > 0.0 && num > 0.0) {
                f = pow(num / den, 2.0 / 3.0);
                for (a = 0; a < 5; a++)
                    dS[a] *= f;
                size *= f;
            }
        }
        if (size > step_max)
            for (a = 0; a < 5; a++)
                dS[a] *= step_max / size;
        gslope = dot5(R, dS);
        for (a = 0; a < 5; a++) {
            du[a] = dS[a] / sc[a];
            unew[a] = u[a] + du[a];
        }
        t = 1.0;
        local = err < 1e-6;
        if (kernel(g, unew, sn_))
            return 2;
        if (g->contact) {       /* backtrack on the residual norm */
            double m0 = dot5(R, R);
            en = residual(sn_, Fsx, fixed, Fs_ext, Rn);
            for (k = 0; k < (local ? 0 : 40); k++) {
                if (dot5(Rn, Rn) <= m0)
                    break;
                t *= 0.5;
                for (a = 0; a < 5; a++)
                    unew[a] = u[a] + t * du[a];
                if (kernel(g, unew, sn_))
                    return 2;
                en = residual(sn_, Fsx, fixed, Fs_ext, Rn);
            }
        } else if (!local) {
            phi0 = 0.0;
            ph = 0.0;
            for (j = 0; j < g->Z; j++) {
                phi0 += st->Q[j] * st->delta[j];
                ph += st->Kn[j] * sn_->delta[j] * sn_->delta[j] * sqrt(sn_->delta[j]);
            }
            phi0 = 0.4 * phi0 - dot5(F, u);
            ph = 0.4 * ph - dot5(F, unew);
            if (!(ph <= phi0 + 1e-4 * gslope)) {
                for (k = 0; k < 59; k++) {
                    t *= 0.5;
                    for (a = 0; a < 5; a++)
                        unew[a] = u[a] + t * du[a];
                    if (potential(g, unew, st->Kn, F) <= phi0 + 1e-4 * t * gslope)
                        break;
                }
                for (a = 0; a < 5; a++)
                    unew[a] = u[a] + t * du[a];
                if (kernel(g, unew, sn_))
                    return 2;
            }
        }
        if (!g->contact)
            en = residual(sn_, Fsx, fixed, Fs_ext, Rn);
        dmx = sn_->dmax;
        umx = 0.0;
        for (a = 0; a < 5; a++)
            if (fabs(unew[a] * sc[a]) > umx)
                umx = fabs(unew[a] * sc[a]);
        fl = 0.0;
        if (dmx > 0.0) {
            fl = eps20 * umx / dmx;
            if (fl < 100.0 * rtol)
                fl = 100.0 * rtol;
            if (fl > cap)
                fl = cap;
        }
        floor_ = fl >= en && en > 0.5 * err;
        memcpy(u, unew, sizeof unew);
        memcpy(R, Rn, sizeof Rn);
        err = en;
        tmp = st; st = sn_; sn_ = tmp;
        if (err < best_err) {
            best_err = err;
            memcpy(best_u, u, sizeof best_u);
        }
        if (floor_ && !(err <= rtol))
            break;
    }
    *iters = it;
    for (a = 0; a < 5; a++)
        if (!isfinite(u[a]))
            return 2;
    return 0;
}

static PyObject *py_newton_one(PyObject *self, PyObject *args)
{
    Py_buffer pack;
    double F[5], fixed[5], u[5], rtol;
    long max_iter, iters = 0;
    int seat, contact, status = 2;
    Geo g;
    (void) self;
    if (!PyArg_ParseTuple(args, "y*(ddddd)(ddddd)(ddddd)dlpp", &pack,
                          &F[0], &F[1], &F[2], &F[3], &F[4],
                          &fixed[0], &fixed[1], &fixed[2], &fixed[3], &fixed[4],
                          &u[0], &u[1], &u[2], &u[3], &u[4], &rtol, &max_iter, &seat,
                          &contact))
        return NULL;
    if (pack.len >= 10 * (Py_ssize_t) sizeof(double)) {
        const double *p = (const double *) pack.buf;
        g.Z = (int) p[0];
        g.ntab = (int) p[1];
        g.Ri = p[2]; g.A = p[3]; g.x0 = p[4]; g.z0 = p[5]; g.g0 = p[6]; g.Kseat = p[7];
        g.rho0 = p[8]; g.kD = p[9];
        g.contact = contact;
        g.cp = p + 10;
        g.sp = p + 10 + g.Z;
        g.tab = p + 10 + 2 * g.Z;
        if (g.Z >= 1 && g.ntab >= 1
            && pack.len == (Py_ssize_t) ((10 + 2 * g.Z + 2 * g.ntab) * sizeof(double))) {
            if (g.ntab <= MAXTAB)
                status = newton(&g, F, fixed, u, rtol, max_iter, seat, &iters);
        } else {
            PyBuffer_Release(&pack);
            PyErr_SetString(PyExc_ValueError, "newton_one: inconsistent buffer size");
            return NULL;
        }
    }
    PyBuffer_Release(&pack);
    return Py_BuildValue("(il(ddddd))", status, iters, u[0], u[1], u[2], u[3], u[4]);
}

static PyMethodDef methods[] = {
    {"newton_one", py_newton_one, METH_VARARGS,
     "newton_one(pack, F, fixed, u0, rtol, max_iter, seat, contact) -> (status, iterations, u)"},
    {NULL, NULL, 0, NULL}
};

static struct PyModuleDef module = {
    PyModuleDef_HEAD_INIT, "_ldkernel",
    "Compiled one-case Newton iteration of ballrace.analytic.loaddist (optional).", -1,
    methods, NULL, NULL, NULL, NULL
};

PyMODINIT_FUNC PyInit__ldkernel(void)
{
    return PyModule_Create(&module);
}
