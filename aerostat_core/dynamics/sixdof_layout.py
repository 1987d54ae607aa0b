"""Index layout of the 6-DOF entries of the kernel parameter vector ``prm`` (after the 3-DOF
ones of :mod:`.layout`); filled by :class:`aerostat_core.dynamics.sixdof.System6` and
:meth:`~aerostat_core.dynamics.sixdof.System6.data` (docs/dynamics.md §7.1)."""

from aerostat_core.dynamics.layout import P_SIZE

# --- 6-DOF entries of the parameter vector (after the 3-DOF ones) ----------------------------
Q_MINV = P_SIZE  # 36 entries: inverse of the 6x6 generalised mass matrix (row major)
Q_IO = Q_MINV + 36  # 9 entries: rigid inertia tensor about O incl. the top half segment
Q_IAX = Q_IO + 9  # roll added inertia [kg m2]
Q_FIN_SIDE = Q_IAX + 1  # vertical / horizontal projected fin area [-]
Q_FIN_KP = Q_FIN_SIDE + 1  # fin roll-damping coefficient K_p [m4]: M_x = -rho |u_f| K_p p
Q_YA = Q_FIN_KP + 1  # winch y [m]
Q_AZ = Q_YA + 1  # reference wind azimuth chi_0 [rad] (direction the wind blows to, from x)
Q_VEER = Q_AZ + 1  # veer rate d chi/dz [rad/m]
Q_VEER_Z = Q_VEER + 1  # height of zero veer [m]
Q_DIR_STEP = Q_VEER_Z + 1  # direction change [rad]
Q_DIR_T0 = Q_DIR_STEP + 1  # its start [s]
Q_DIR_TR = Q_DIR_T0 + 1  # its (1 - cos) ramp time [s]
Q_GV_AMP = Q_DIR_TR + 1  # crosswind gust amplitude [m/s] (0: none)
Q_GV_T0 = Q_GV_AMP + 1  # its start [s]
Q_GV_TR = Q_GV_T0 + 1  # its rise time d_m/U_c [s]
Q_GV_CONV = Q_GV_TR + 1  # 1: convected with the mean wind
Q_TV_ON = Q_GV_CONV + 1  # 1: lateral turbulence rows appended to the turbulence table
Q_BREAK_T = Q_TV_ON + 1  # tether break time [s] (inf: never)
Q_REEL_T0 = Q_BREAK_T + 1  # reel start [s]
Q_REEL_SPEED = Q_REEL_T0 + 1  # reel speed [m/s], > 0 pays out, < 0 reels in (0: none)
Q_REEL_RAMP = Q_REEL_SPEED + 1  # (1 - cos) speed ramp [s]
Q_REEL_T1 = Q_REEL_RAMP + 1  # reel end [s] (start of the ramp down)
Q_LEN0 = Q_REEL_T1 + 1  # initial unstretched tether length [m]
Q_QSTAB = Q_LEN0 + 1  # quaternion norm stabilisation gain [1/s]
Q_IA = Q_QSTAB + 1  # pitch/yaw added inertia [kg m2]
Q_MY = Q_IA + 1  # lateral added mass [kg]
Q_FIN_CD0 = Q_MY + 1  # zero-lift part of the fin drag table per unit q [m2]
Q_ZW = Q_FIN_CD0 + 1  # winch z again (ground level for the checks) [m]
Q_SIZE = Q_ZW + 1
