"""Index layout of the flat parameter vector ``prm`` shared by the numba kernels.

Module-level integers are compile-time constants for numba. Keep this file in sync with
:class:`aerostat_core.dynamics.system.DynamicSystem` (which fills ``prm``). The diagnostics both
kernels write (:data:`DIAG_NAMES`), the hull's wind stations and the reader of the aerodynamic
tables (:func:`table_lookup`) are here too, once for the 3- and the 6-DOF kernels.
"""

from numba import njit

# --- general ---------------------------------------------------------------------------------
P_MODE = 0  # 0 = point aerostat, 1 = rigid hull (3 DOF), 2 = 6-DOF hull (:mod:`.sixdof_kernel`)
P_NSEG = 1  # number of tether segments N
P_G = 2  # gravity [m/s2]
P_RHO_Z0 = 3  # first height of the air-density table [m]
P_RHO_DZ = 4  # spacing of the air-density table [m]
P_RHO_REF = 5  # reference density for added masses [kg/m3]
P_XA = 6  # winch x [m]
P_ZA = 7  # winch z [m]
# --- tether ----------------------------------------------------------------------------------
P_L0 = 8  # unstretched segment length [m]
P_W = 9  # mass per length [kg/m]
P_D = 10  # diameter [m]
P_EA = 11  # axial stiffness [N]
P_CD = 12  # internal damping c/l0 [N s/m] (tension += c * ldot / l0)
P_CDN = 13  # normal drag coefficient [-]
P_CDT = 14  # tangential drag coefficient on pi d [-]
P_TBUOY = 15  # 1: air buoyancy of the line on
P_TDRAG = 16  # 1: tether drag on
# --- point aerostat --------------------------------------------------------------------------
P_PM = 17  # mass [kg]
P_PV = 18  # volume [m3]
P_PCDA = 19  # drag area C_D A [m2]
P_PCA = 20  # added-mass coefficient [-]
# --- hull ------------------------------------------------------------------------------------
P_HM = 21  # hull mass incl. gas, payload ... [kg]
P_HV = 22  # displaced volume [m3]
P_XG = 23  # CG body x (forward of the CV) [m]
P_ZG = 24  # CG body z (below the CV) [m]
P_XC = 25  # confluence point body x [m]
P_ZC = 26  # confluence point body z [m]
P_XF = 27  # fin aerodynamic centre body x [m]
P_ZF = 28  # fin aerodynamic centre body z [m]
P_MX = 29  # axial added mass [kg]
P_MZ = 30  # transverse added mass [kg]
P_IA = 31  # rotational added inertia [kg m2]
P_MINV = 32  # 9 entries: inverse of the 3x3 generalised mass matrix (row major)
P_MT = 41  # rigid mass incl. the top half tether segment [kg]
P_XGT = 42  # its CG body x [m]
P_ZGT = 43  # its CG body z [m]
P_CDC = 44  # hull cross-flow drag coefficient (C_dc)_h [-]
P_UNSTEADY = 45  # 1: unsteady-wind inertia (added mass x fluid acceleration + Froude-Krylov)
P_KIRCHHOFF = 46  # 1: add the Kirchhoff Munk moment (m_z - m_x) u_r w_r (only with J&D off!)
P_AERO_INV = 47  # 1: J&D inviscid hull term
P_AERO_AX = 48  # 1: hull axial drag
P_AERO_CF = 49  # 1: hull cross-flow strips
P_AERO_FIN = 50  # 1: fins
P_AL0 = 51  # first angle of the aero tables [rad]
P_DAL = 52  # spacing of the aero tables [rad]
P_V0 = 53  # first airspeed of the drag-coefficient table [m/s]
P_DV = 54  # spacing of the drag-coefficient table [m/s]
P_THETA_MAX = 55  # pitch limit for the divergence check [rad]
P_POINT_FK = 56  # point aerostat: 1 = Froude-Krylov + added mass x fluid acceleration
P_TPUSH = 57  # 1: the tether damper may push (MoorDyn convention); 0: no compression
P_SIZE = 58

# rows of the aero table ``tab`` (per unit dynamic pressure, from the static engine's functions)
T_N_INV = 0  # inviscid normal force / q [m2]
T_A_INV = 1  # inviscid axial force / q [m2]
T_M_INV = 2  # inviscid moment about the CV / q [m3]
T_A_AX = 3  # axial drag / (q * C_DV ratio) [m2]
T_FIN_L = 4  # fin lift / q [m2]
T_FIN_D = 5  # fin drag / q [m2]
T_ROWS = 6

#: Diagnostic outputs of the 3-DOF right-hand side (the 6-DOF kernel writes them first, with the
#: same meanings, then its own: :data:`.sixdof_kernel.DIAG6_NAMES`).
DIAG_NAMES = (
    "alpha",  # angle of attack at O [rad] (point: 0)
    "airspeed",  # relative airspeed at O [m/s]
    "wind_x",  # wind at O (or the point) [m/s]
    "wind_z",
    "tension_top_x",  # force the body exerts on the tether at its top (C) [N]
    "tension_top_z",
    "tension_winch_x",  # force the tether exerts on the winch [N]
    "tension_winch_z",
    "tension_max",  # largest segment tension [N]
    "x_top",  # confluence point (or point aerostat) position [m]
    "z_top",
    "vx_top",  # its velocity [m/s]
    "vz_top",
    "vx_body",  # velocity of O (hull) or of the point [m/s]
    "vz_body",
    "alpha_fin",  # local angle of attack at the fins [rad]
    "fin_lift",  # fin lift [N]
    "aero_moment",  # aerodynamic pitching moment about O, nose-up [N m]
    "tension_min",  # smallest segment tension [N] (0: a slack segment)
    "wind_accel_x",  # fluid acceleration DU_x/Dt at O [m/s2]
    "tension_min_segment",  # segment with the smallest tension, 1 = at the winch [-]
)
ND = len(DIAG_NAMES)
#: Stations along the hull where the cross-flow strips sample a spatially varying wind [-].
N_STATIONS = 6


@njit(cache=True)
def table_lookup(tab, row, x, x0, dx):  # pragma: no cover - numba
    """Linear interpolation in row ``row`` of a uniform table (clamped at the ends)."""
    m = tab.shape[1]
    s = (x - x0) / dx
    if s <= 0.0:
        return tab[row, 0]
    if s >= m - 1:
        return tab[row, m - 1]
    k = int(s)
    f = s - k
    return tab[row, k] * (1.0 - f) + tab[row, k + 1] * f
