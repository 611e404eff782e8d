"""
The solved shaft as a ROSS rotor: critical speeds
=================================================

A shaft solved on its ball bearings hands its seats' stiffness at the operating point to
ROSS (``pip install 'ballrace[rotor]'``, ross-rotordynamics): ``shaft.ross_bearings``
builds one ROSS ``BearingElement`` per seat (kxx, kxy, kyx, kyy lateral and kzz axial,
ROSS axes (x, y, z) = ballrace (y, z, x)), and a ROSS rotor with one ``ShaftElement``
per interval of ``result.nodes`` numbers its nodes as ballrace does.

1. The gearbox shaft of the previous example, its helical gear a steel disc: the first
   critical speeds at standstill (ROSS ``run_modal``).
2. A check: a uniform shaft with a seat at each end.  On very stiff bearings ROSS's first
   bending frequency is that of a simply supported beam; on the ballrace bearings it is
   lower.  The bearings' tilt stiffness, which a ROSS bearing does not carry, added to
   ROSS's stiffness matrix by hand: hardly a change here,
3. but 7 % on a spindle with a preloaded pair of angular-contact bearings.

Simply supported beam, mode 1 (k = pi/L): Euler–Bernoulli
f1 = (pi/L)^2 sqrt(EI/(rho A)) / (2 pi); Timoshenko (shear with Cowper's kappa and rotary
inertia, as ROSS's shaft element) the lower root of
(rho^2 I/(kappa G)) w^4 - (rho A + rho I k^2 (1 + E/(kappa G))) w^2 + E I k^4 = 0
(Timoshenko 1921, Phil. Mag. 41, 744-746: his two beam equations with
w = sin(kx) exp(i w t) give it).

Without ROSS the script prints a note and computes the beam formulas only.
"""
import numpy as np

import ballrace
from ballrace.analytic import duplex as dx
from ballrace.analytic import shaft

try:
    import ross
    ross.Rotor            # (not some other directory called "ross" on the path)
except (ImportError, AttributeError):       # the documentation build has no ROSS
    ross = None

steel = ballrace.Material(E=210e9, nu=0.3, density=7850.0)
brg = ballrace.BallBearing(12.7e-3, 9, 60e-3, 0.52, 0.525, diametral_clearance=15e-6)

# %%
# The beam formulas for the check shaft: 500 mm, solid 40 mm, a seat at each end.
L, D = 0.5, 0.040
E, nu, rho = steel.E, steel.nu, steel.density
G = E / (2 * (1 + nu))
A, I = np.pi * D**2 / 4, np.pi * D**4 / 64
kappa = float(shaft.shear_coefficient(nu))      # Cowper (1966), as ROSS's "cowper"
k = np.pi / L
f_eb = k**2 * np.sqrt(E * I / (rho * A)) / (2 * np.pi)
a4 = rho**2 * I / (kappa * G)
b2 = rho * A + rho * I * k**2 * (1 + E / (kappa * G))
c0 = E * I * k**4
f_timoshenko = np.sqrt(2 * c0 / (b2 + np.sqrt(b2**2 - 4 * a4 * c0))) / (2 * np.pi)
print(f"simply supported, mode 1: Euler-Bernoulli {f_eb:.2f} Hz, "
      f"Timoshenko {f_timoshenko:.2f} Hz")
KEY = {"ross": ross is not None, "f_eb": f_eb, "f_timoshenko": f_timoshenko,
       "slenderness": L / D, "kappa": kappa, "nu": nu}

if ross is None:
    print("ROSS (ross-rotordynamics) is not installed: pip install 'ballrace[rotor]' "
          "to build the rotor.")
else:
    rmat = ross.Material(name="ballrace_steel", rho=rho, E=E, Poisson=nu)
    # ballrace (u, v, w, theta_y, theta_z) -> ROSS node DOFs (x, y, z, alpha, beta, theta)
    TO_ROSS = np.array([2, 0, 1, 3, 4])

    def rotor(result, bearings, disks=()):
        """A ROSS rotor of the solved shaft: one ShaftElement per interval of its nodes."""
        nd = result.nodes
        els = []
        for i, (a, b) in enumerate(zip(nd[:-1], nd[1:])):
            Do, Di = result.shaft.diameters(0.5 * (a + b))
            els.append(ross.ShaftElement(L=float(b - a), idl=float(Di), odl=float(Do),
                                         material=rmat, n=i))
        return ross.Rotor(els, disk_elements=list(disks), bearing_elements=bearings)

    def bending(K, M, n=4):
        """Lowest n undamped frequencies [Hz] of modes that are mostly lateral (x, y)."""
        from scipy.linalg import eigh

        keep = np.flatnonzero(np.diag(M) > 0)
        w2, V = eigh(K[np.ix_(keep, keep)], M[np.ix_(keep, keep)])
        dof = keep % 6
        lat = np.isin(dof, (0, 1))
        MV = M[np.ix_(keep, keep)] @ V
        share = (V[lat] * MV[lat]).sum(0) / (V * MV).sum(0)
        return np.sqrt(np.clip(w2[share > 0.5], 0, None))[:n] / (2 * np.pi)

    # %%
    # 1. The gearbox shaft (plot_15) with its gear as a 30 mm wide steel disc.
    s = shaft.Shaft([(0.03, 0.04, 0.0), (0.2, 0.048, 0.0), (0.03, 0.04, 0.0)], steel)
    seats = [shaft.Seat(0.015, brg, name="A"), shaft.Seat(0.245, brg, floating=True,
                                                         name="B")]
    gear = shaft.gear_mesh(0.09, 5000.0, 0.12, helix_angle=np.radians(15),
                           mesh_azimuth=np.radians(90))
    r = shaft.solve(s, seats, [gear])
    for c in shaft.bearing_coefficients(r):
        print(f"seat at {c['x'] * 1e3:5.1f} mm (node {c['node']}): kxx {c['kxx']:.3e}  "
              f"kyy {c['kyy']:.3e}  kxy {c['kxy']:.2e}  kzz {c['kzz']:.3e} N/m")
    n_gear = int(np.argmin(np.abs(r.nodes - gear.position)))
    disc = ross.DiskElement.from_geometry(n=n_gear, material=rmat, width=0.03,
                                          i_d=0.048, o_d=0.12, tag="gear")
    gearbox = rotor(r, shaft.ross_bearings(r), [disc])
    modal = gearbox.run_modal(speed=0.0, num_modes=12)
    wn = np.asarray(modal.wn)
    f_ross = wn[wn > 1.0] / (2 * np.pi)
    print("gearbox shaft, ROSS run_modal at standstill [Hz]:",
          np.array2string(f_ross[:6], precision=1))
    f_gear = bending(gearbox.K(0), gearbox.M(0))
    print("  bending modes from ROSS's K, M [Hz]:", np.array2string(f_gear, precision=1),
          f" first critical speed {f_gear[0] * 60:.0f} rpm")

    # %%
    # 2. The check shaft: a belt pull of 3 kN in the middle loads the bearings.
    s2 = shaft.Shaft([(L, D, 0.0)], steel)
    seats2 = [shaft.Seat(0.0, brg, name="A"), shaft.Seat(L, brg, floating=True, name="B")]
    r2 = shaft.solve(s2, seats2, [shaft.belt_pull(L / 2, 3000.0)])
    stiff = [ross.BearingElement(n=c["node"], kxx=1e12, kyy=1e12, kzz=1e12, cxx=0.0)
             for c in shaft.bearing_coefficients(r2)]
    rs = rotor(r2, stiff)
    f_stiff = bending(rs.K(0), rs.M(0))[0]

    def tilt_choices(result):
        """First bending frequency [Hz] with tilt="held", tilt="free" and with the seats'
        whole 5x5 stiffness (tilts included) put into ROSS's K at the seat nodes by hand."""
        held = rotor(result, shaft.ross_bearings(result, tilt="held"))
        M, K_held = held.M(0), held.K(0)
        K_free = rotor(result, shaft.ross_bearings(result, tilt="free")).K(0)
        K_full = K_held.copy()
        for c in shaft.bearing_coefficients(result):
            i = 6 * c["node"] + TO_ROSS
            Kg = np.zeros((5, 5))
            Kg[np.ix_([0, 1, 2], [0, 1, 2])] = [[c["kzz"], 0, 0], [0, c["kxx"], c["kxy"]],
                                                [0, c["kyx"], c["kyy"]]]
            K_full[np.ix_(i, i)] += c["stiffness"] - Kg
            print(f"  seat at {c['x'] * 1e3:5.1f} mm: tilt stiffness "
                  f"{c['stiffness'][3, 3]:.3g}, {c['stiffness'][4, 4]:.3g} N m/rad")
        return [bending(Kx, M)[0] for Kx in (K_held, K_free, K_full)]

    f_held, f_free, f_full = tilt_choices(r2)
    print(f"check shaft, first bending frequency [Hz]: stiff bearings {f_stiff:.3f} "
          f"(Timoshenko {f_timoshenko:.3f}, {f_stiff / f_timoshenko - 1:+.1e}; "
          f"Euler-Bernoulli {f_eb:.3f}, {f_stiff / f_eb - 1:+.1e})")
    print(f"  on the ballrace bearings: tilt held {f_held:.2f}, tilt free {f_free:.2f}, "
          f"with the tilt stiffness {f_full:.2f}")

    # %%
    # 3. Where the tilt stiffness matters: a spindle (350 mm, 60/30 mm) with a DB pair of
    # 25 deg angular-contact bearings (1.5 kN preload, rows 18 mm apart) at the front and a
    # floating deep-groove bearing at the rear, 1 kN on the nose.
    ac = ballrace.BallBearing(9.525e-3, 15, 65e-3, 0.52, 0.53,
                              free_contact_angle=np.radians(25))
    dg = ballrace.BallBearing(12.7e-3, 9, 60e-3, 0.52, 0.525, diametral_clearance=0.0)
    pair = dx.DuplexPair(ac, "DB", preload=1500.0)
    r3 = shaft.solve(shaft.Shaft([(0.35, 0.06, 0.03)], steel),
                     [shaft.Seat(0.02, pair, row_spacing=0.018, name="front"),
                      shaft.Seat(0.3, dg, floating=True, name="rear")],
                     [shaft.PointLoad(0.0, Fy=1000.0)])
    sp_held, sp_free, sp_full = tilt_choices(r3)
    print(f"spindle, first bending frequency [Hz]: tilt held {sp_held:.2f}, tilt free "
          f"{sp_free:.2f}, with the tilt stiffness {sp_full:.2f}")
    KEY.update(f_gearbox=f_gear, f_ross_modal=f_ross, f_stiff=f_stiff, f_held=f_held,
               f_free=f_free, f_full=f_full, spindle=(sp_held, sp_free, sp_full))
