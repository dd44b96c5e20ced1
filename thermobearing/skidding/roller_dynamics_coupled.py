"""All rollers and the cage integrated together (paper 003 eqs. 18-19, ring prescribed).

Zhang et al. 2021, seed ``003_743e023ae6e45686.txt`` [zhang2021_abnormal_wear], integrate
every roller (eq. 18), the cage (eq. 19) and the inner ring (eq. 20) together with a stiff
variable-step method (GSTIFF [gear1971_dae]). The reduced and the one-roller "full" model of
:mod:`~thermobearing.skidding.roller_dynamics` prescribe the roller spins and the cage speed
(the quasi-static balance of :func:`~thermobearing.skidding.roller_dynamics.couple_spins`).
Here the spins and the cage speed are degrees of freedom:

* per roller j (Z of them): X, X', alpha, alpha', z, z' (the right-hand side of the one-roller
  model, :func:`~thermobearing.skidding.roller_dynamics._rhs`: rib eqs. 1-17, cage bars,
  unbalance), the unbalance phase psi and the spin omega_j,
  J_p omega_j' = (D/2)(S_j - f_bar,j) + M_rib,x,j, with S_j the raceway shear of paper 000's
  traction model (:func:`thermobearing.skidding.roller.evaluate`: roller moment balance
  plus its pocket friction) and f_bar,j the pocket-film friction (paper 000 eqs. 37-38,
  :func:`~thermobearing.skidding.roller_fluid.pocket_forces`) at the instantaneous bar force;
  the raceways' net orbital force F_d,j of the same evaluation drives z;
* cage: angle theta_c and speed omega_c, J_c omega_c' = sum_j [-F_bar,z,j d_m/2 - f_bar,j D/2]
  - T_c (eq. 19 line 3 with the bar forces of the rollers; T_c the quasi-static model's cage
  drag torque), roller azimuths phi_j = phi_j0 + theta_c;
* inner ring: prescribed (no whirl), its loads per azimuth from the quasi-static solution --
  eq. 20 is not integrated.
* option ``tilt`` of the model (:func:`~thermobearing.skidding.roller_dynamics.build_model`):
  per roller also the radial position y_r and the tilt alpha_e with their speeds (eq. 18's
  remaining DOFs; :mod:`~thermobearing.skidding.roller_dynamics_tilt`), stored after the
  ring's X, X' in the state; ``series["radial"]`` and ``series["tilt"]`` (time x Z) hold
  y_r [m] and alpha_e [rad], and the samples' X, X' are those the rib faces see (plus
  t_q alpha_e, t_q alpha_e').

Integrator (ours): paper 000's traction evaluation costs ~4 ms per call (Python/numpy over Z
rollers), the rib contact needs steps <= 1/omega_rib (~1.6 us): the raceway shear and
orbital force are linearised in (omega_j, omega_c) -- value and forward-difference slopes --
and refreshed every ``refresh`` seconds (default 20 us, 1/5 of the loaded rollers' spin time
constant J_p/k), the contact-resolved motion integrated by classical RK4 (ETDRK4 since
2026-11-23, "Stiff spin" below) at the reduced model's step in between (a multirate, locally
linearised scheme). The whole time loop is one jitted kernel (:func:`_integrate`). The
linearisation comes from paper 000's model tabulated once per run over (omega_r, N_i,
omega_c) and interpolated inside the kernel (``traction="table"``, default,
:mod:`~thermobearing.skidding.roller_dynamics_table`) or, as a reference, from three
``evaluate`` calls per refresh made from Python between kernel calls
(``traction="evaluate"``). Measured at the paper 003 base case (0.06 / 0.11 g, 1.5 + 1.5
orbits, 2026-11-22): table 1.1 s CPU per point, evaluate 3.9-5.4 s, the previous
Python-driven RK4 loop 7.6-11.8 s; slip 5.23 / 5.51 (table) vs 5.23 / 5.51 (evaluate) vs
5.27 / 5.64 m/s (previous loop), PV 1231 / 1281 vs 1210 / 1246 vs 1206 / 1272 MPa m/s: the
differences are those of the chaotic impacting motion under floating-point-level changes
(validation case SOURCE.md). Refresh convergence is checked in the tests. Units: SI.

Stiff spin (2026-11-23): the integrator is ETDRK4 (``integrator="etd"``, default;
:mod:`~thermobearing.skidding.roller_dynamics_etd`): each roller's spin relaxation under the
linearised raceway shear, lambda = (D/2) dS/d omega / J_p, and the pocket speed's raceway
damping -c_z/m are integrated exactly (:func:`_stiff_rates`), everything else by the RK4
stages (ETDRK4 is RK4 where lambda = 0). With a mineral oil the film's Newtonian shear gives
|lambda| up to ~3e7 1/s (ISO VG46 at 80 degC, CRB 50x75x16, 20000 r/min, 3 kN: h |lambda|
= 60 for the most loaded roller at the default step; RK4's bound is 2.8): explicit RK4 ran
to a non-finite state there even at 6400 steps per spin period on the evaluate path; ETDRK4
converges at the default step (tests). The shear also reaches its limit within ~1 rad/s of
the equilibrium spin, far inside the table's 50 rad/s spin step: the table's interpolant
smears it over ~2 spin cells, and a linearisation held for the 20 us refresh let a roller
coasting on the saturated, flat part of the curve overshoot its equilibrium by ~1000 rad/s
(the spins then reversed and left the table 21 times: the "unstable coupled motion" the
rib heat source fell back from). On the table path each roller's linearisation is
therefore renewed in the kernel as soon as its spin moved by more than
:data:`SPIN_TRUST` x the table's spin step from its linearisation spin. Measured
(2026-11-23; paper 003 base case, 30000 r/min, MIL-PRF-23699, 2 + 3 orbits, default step):
0.11 g RK4 / ETDRK4 PV 629.1 / 632.1 (left), 634.5 / 630.8 (right) MPa m/s, slip 5.480 /
5.471 m/s, rib heat 72.09 / 72.28 W per roller, CPU 1.22-1.41 / 1.13-1.27 s per point; at
1600 steps per period RK4 / ETDRK4 633.4 / 630.0, 633.9 / 626.1 MPa m/s, 5.495 / 5.475 m/s,
72.64 / 71.92 W (differences inside the chaotic motion's scatter); 0.06 g 596.4 / 597.0,
592.9 / 597.3 MPa m/s, 5.042 / 5.192 m/s, 52.53 / 52.95 W. ISO VG46 at 80 degC, 20000
r/min (no unbalance, previously "unstable coupled motion"): slip 1.7048 m/s, rib heat
0.0585 W per roller at 400, 1600 and 3200 steps per period (0.66 s CPU); at 40 degC, 5000
r/min (previously a spin runaway): slip 2.0123 / 2.0122 m/s at 400 / 1600.
Over ISO VG32 / 46 / 68 / 100, OIL_4109 and PAPER000_OIL at 40 / 80 degC and 5000 / 20000
r/min (3 kN, no unbalance) 16 of 20 states stopped on RK4 and all 20 run on ETDRK4 with one
table. Limits measured on ISO VG46, 80 degC, 20000 r/min (2 + 2 orbits): the table's
spin grid smears the shear's sharp knee, slip 1.7050 / 1.7079 / 1.7382 m/s at a 50 / 12.5 /
3.125 rad/s spin step (rib heat 0.0585 -> 0.0587 W per roller); the evaluate path cannot
renew inside the kernel and overshoots with its 20 us refresh, slip 1.875 (1.791 at 5 us),
so a table-path run that falls back to it carries that error (renewing it in the kernel
measured 6-10x its CPU, also at paper 003's base case: not done). OIL_4109 at 40 degC:
ETDRK4 3.0328 m/s at 400 and 1600 steps per period, RK4 3.178 after 5 table rebuilds and
divergent on a 12.5 rad/s spin grid (ETDRK4 there 2.999).
``integrator="rk4"`` keeps the previous explicit scheme (no in-kernel renewal) for
comparison.

Pocket damping units (2026-11-23). The pocket speed's raceway damping c_z (m z'' = ... -
c_z z', :func:`~thermobearing.skidding.roller_dynamics_rhs._rhs_ring`, [N s/m]) was set to
-dS/d omega of the linearisation [N s/rad]. Eq. 18 puts the same raceway tractions in the
roller's circumferential translation and, times D/2, in its spin, so dF_d/dz' =
(dS/d omega)/(D/2): now c_z = max(-(dS/d omega)/(D/2), 0) on both traction paths
(:func:`~thermobearing.skidding.roller_dynamics_coupled_kernels.pocket_damping`, the
reduced model's k_omega/(D/2)^2), 333x the previous value for the 6 mm roller. Paper 003
base case: 6.45 N s/m for the most loaded roller (was 0.019), 0.057 unloaded; with
MIL-PRF-23699 at 30000 r/min the traction is linear in z' to 0.03 % up to 1 m/s. Measured
(2 + 3 orbits, ETDRK4, 400 steps per period) before -> after: no unbalance slip 4.876 ->
5.148 m/s; 0.06 g PV 597.0 / 597.3 -> 668.0 / 665.7 MPa m/s (left / right), slip 5.192
-> 5.192 m/s; 0.11 g PV 632.1 / 630.8 -> 663.9 / 663.4, slip 5.471 -> 5.475, rib heat
72.3 -> 74.8 W per roller. Over 16 trajectories per mass (400 .. 3200 and 384 .. 417
steps per period) without a runaway: PV 603 -> 668 (0.06 g) and 630 -> 656 MPa m/s
(0.11 g; standard errors 1.3-1.8), slip 5.134 -> 5.145 and 5.458 -> 5.470 m/s: PV no longer
grows from 0.06 to 0.11 g (ratio 1.045 -> 0.981). Trajectories entering the cage-runaway
regime ("Cage runaway" below; |X| > 30 um): 2 -> 4 of 32; at 10000 r/min, 0.11 g, 7 of 7
distinct trajectories (refresh 14-24 us) left the 20 % cage band within 5 orbits (2 of 7
before; peaks 1.23-1.43 x quasi-static): an unloaded roller jammed on its rib (X = -30
um, spin held near omega_i) drags ~100 N onto its front bar and drives the cage. Limits:
c_z is the linearisation's slope; where the film is Newtonian near pure rolling (ISO
VG46, 80 degC, 20000 r/min: 9.5e4 N s/m for the loaded rollers) the traction saturates
at ~128 N within |z'| ~ 1e-3 m/s, so the linear damping overstates the resistance to a
faster pocket motion (not followed here; slip there 1.7048 -> 2.1278 m/s, step-converged
to 5e-4); that pocket speed is stiff (h c_z/m = 30), which ETDRK4 integrates exactly per
component, but its coupling to the stiff spin goes through the explicit stages: the
state error at the default step grew (tests/unit/test_roller_dynamics_etd.py).

Spin-pocket coupling (2026-11-23, evening). Each raceway contact's shear is a function of
its own sliding speed; a pocket speed z' lowers the inner one's by z' and raises the outer
one's by z', so the spin equation's shear changes by dS/dz' = (dS_i/d omega - dS_o/d
omega)/(D/2) (:func:`~thermobearing.skidding.roller_dynamics_coupled_kernels.
spin_pocket_coupling`; the table carries the outer shear as a column of its own). The
pocket damping c_z needs no split: it is the *sum* of the two contacts' slopes, which the
summed shear's spin slope gives exactly (measured at paper 003's base case: k_i + k_o =
3.377 + 3.074 = 6.451 N s/m = c_z); the per-contact nonlinearity of F_d over the pocket
speeds of the motion (rms 1.36 m/s at 30000 r/min, 0.40 at 10000) is <= 0.05 N at 1 m/s
(0.10 N at 10000 r/min): ~1 % of c_z z' for the loaded rollers, 12-38 % of the <= 0.25 N
of the lightly loaded and unloaded ones; not followed. Before, S was held at its
z' = 0 value: at z' = 0.5 m/s the most loaded roller's shear is 0.329 N in paper 000's
model, 0.469 N held, 0.318 N now (30000 r/min; 10000 r/min: -0.760 / 0.128 / -0.825 N).

Runaway mechanism (2026-11-23, evening; validation case SOURCE.md): the cage runaways are
a friction-driven axial/skew rattle of one *unloaded* roller wedged between its ribs. The
300 mm end-face sphere meets both ribs at a skew of ~sqrt(C_a/(R_s - L_r/2)) = 10 mrad;
there the roller rattles at ~44 kHz between X = +-30 um with rib forces of ~6000 N, its spin
held near 1050 rad/s, pressed on its front bar with ~176 N, which drives the cage. The
energy comes from the rib friction's work on the skew (0.9 J over 1 ms, checked along the
trajectory) and nothing takes it out: the Hertz rib contact (paper 003 eq. 6) is elastic
and an unloaded roller's only raceway damping is its outer contact under the centrifugal
load (9.1 N at 10000 r/min against 77 N at 30000 r/min -- why this point). The single
roller's equations integrated with an adaptive DOP853 (rtol 1e-8) show the same growth
(kinetic energy 1.5e-3 -> 6e-2 J in 3 ms): not the step. Without the rib friction, or with
10x the outer contact's axial damping, it decays. The model option ``rib_squeeze``
(:func:`thermobearing.rib.face_squeeze`, the rib gap's squeeze film) removes it, but also
keeps the rollers off the ribs at the base case (PV ~0): not the default.

Cage settling (2026-11-23, night; validation case SOURCE.md "Cage settling"). From the
quasi-static start the rollers' spins (and the axial / pocket states) first come to their
balance with the dynamics' drags, the cage following them: where that is slow the fixed
2-orbit warm-up leaves a creeping cage in the statistics window. Measured (MIL-PRF-23699,
30000 r/min, no unbalance, 400 steps per spin period): 3000 N, 80 degC settles to 0.5 %
within 1 orbit (window slip +0.13 % off the 40-orbit value); 1000 N, 80 degC creeps for
~7 orbits (orbit-to-orbit ratio ~0.69; window cage -1.7 %, slip +8.1 %); 3000 N, 400 K
1311 -> 1343.7 rad/s over ~10 orbits (window slip +4.8 %). Starting from the settled cage
speed does not remove it (the cage first falls, then creeps back: the rollers drive it).
``settle`` = a relative tolerance (default None; the rib heat source and the paper 003
runner's points without unbalance use :data:`DEFAULT_SETTLE` = 1e-3) warms up in whole
orbits, at least max(2, ceil(``warmup_orbits``)), at most ``settle_max_orbits``
(:data:`SETTLE_MAX_ORBITS` = 16), until the settling test
(:func:`~thermobearing.skidding.roller_dynamics_convergence.creep_settled`) passes on the
orbit-mean cage speeds (cage angle over time) of the last two orbits and of the orbit
between them (half an orbit later than the first): the orbit-to-orbit change <= ``settle``,
no turning point, and the remainder of the geometric creep extrapolated from the ratio of
the two half-orbit-lag changes, floored by the cage mode's own decay over half an orbit
(:func:`~thermobearing.skidding.roller_dynamics_convergence.cage_mode_ratio` from the
linearisation's sum_j dF_d,j/d omega_c at the test; ``series["settle_ratio_floor"]``),
<= ``settle``. The window then keeps its length. With ``converge`` the settling warm-up (at
least 2 orbits) comes first and the running-mean test starts with its last orbit (the one
the test passed on, sampled already: the earliest stop is then 2 orbits). Measured with
1e-3 (2026-11-23, the orbit-to-orbit test then): 1000 N slip 19.965 -> 18.506 m/s
(40-orbit value 18.47), 11 warm-up orbits, CPU 1.3 -> 3.7 s; 400 K 6.236 -> 5.962
(5.952), 7 orbits. With an unbalance the motion is chaotic (orbit-to-orbit cage scatter
0.1-0.5 %, excursions of +1-2 % for 1-2 orbits at 0.06 g): the test passes there by a
chance agreement or runs to its cap, and the window's error is its scatter (3-orbit window
vs 35-orbit mean: PV +0.2 / +1.4 %, slip +1.6 / +0.1 % at 0.06 / 0.11 g), which a longer
warm-up does not reduce. Why the 400 K state creeps (2026-11-24, roller_dynamics_heat
notes "Warm start"): its cage mode is weakly damped (the loaded rollers' traction slope
with the cage speed, ~ oil viscosity: I/D = 14 ms against 4.2 ms at 353 K, measured
e-folding 8 ms = 1.7 orbits) and its quasi-static start is 2.4 % below the settled cage
speed. ``start`` = a previous run's ``series["end_state"]`` (every run returns it: the
roller states, the cage angle and speed, the ring's axial state) starts the integration
there instead of at the quasi-static state (the cage angle taken within its first turn;
a table retry perturbs its cage speed as it does the quasi-static one): from the 395 K
node's end state the 400 K node settles after 4 orbits instead of 8.

Settling test (2026-11-24, issue 9). The test was the orbit-to-orbit change alone
(<= ``settle``); for a geometric creep of ratio r per orbit that leaves ~ settle r/(1 - r)
of it (0.22 % at r = 0.69), and it passed falsely at a turning point: started with the
cage at its settled 1343.7 rad/s (30000 r/min, 400 K) the cage fell to 1337.9 and came
back, orbits 0 and 1 both averaging 1338.72 (-0.37 %). Measured (paper 003 base case
without unbalance, MIL-PRF-23699, 3 kN, the heat source's defaults: converge 5e-3, settle
1e-3; "warm" from the node 5 K cooler, "cage start" the quasi-static state with the cage at
its settled speed; rib heat against a 25 + 10-orbit fixed run: 0.0554367 / 0.0581720 /
0.0420467 W per roller), orbits integrated and heat error, before -> after:

* 20000 r/min, 353 K: cold 3.0, -0.0010 % -> the same; warm 2.0, -0.0021 % -> 2.0,
  -0.0020 %; cage start 2.0, -0.037 % -> 3.0, -0.0011 %.
* 30000 r/min, 400 K: cold 7.0, +0.19 % -> 8.0, +0.11 %; warm 2.0, -0.28 % -> 4.0,
  -0.085 %; cage start 3.7, +0.94 % -> 6.0, +0.099 %.
* 30000 r/min, 440 K: cold 10.0, +0.74 % -> 15.0, +0.17 %; warm 2.0, -0.39 % -> 4.0,
  -0.29 %; cage start 5.0, +3.98 % -> 12.0, +0.098 %.

CPU per node 0.5-0.7 s at 353 K (unchanged), 400 K cold 1.38 -> 1.49 s, warm 0.55 ->
0.89 s, 440 K cold 1.80 -> 2.68 s, warm 0.57 -> 0.90 s. The floor (half an orbit): 0.37
at 353 K, 0.84 at 400 K, 0.91 at 440 K; without it (measured ratio only) the 440 K warm
start still passed after 2 orbits at -0.53 %: its creep is a fast decay over the slow cage
mode, which three windows in two orbits do not show. What is left: the test bounds the
cage speed's remainder to ~ ``settle``; the rib heat moves ~3x the cage speed here (the
440 K warm start's window: cage +0.10 %, heat -0.29 %), so a heat error below 0.1 % at the
hot nodes needs ``settle`` ~ 3e-4 (more orbits; not the default). 1000 N, 80 degC (r ~
0.69): 11 -> 13 warm-up orbits (the cap was 12: raised to 16), slip 18.506 -> 18.490 m/s
(40-orbit value 18.47).

Cage runaway and the fallback (2026-11-22). The example scene
``configs/scenes/crb_rib_example.toml`` with 0.06 g (paper 003's bearing as an NUP variant,
20000 r/min, 3 kN, MIL-PRF-23699) stopped with "the state keeps leaving the traction table":
at 420 K (the "elements" temperature its transient probed) the table path's cage ran from
886 to > 1840 rad/s (21 table rebuilds, each adding two 2.5 % cage layers) while the spins
stayed near 9500 rad/s; one roller (of 24) rattled axially between its ribs to |X| = 47 um
(the others 18 um; axial clearance 30 um) and sat on its front bar 10-17 um deep, ~300 N of
bar force pushing the cage. Not the table's accuracy: along an evaluate-path trajectory
(1 + 1 orbits, 420 K, 2184 refreshes) the table differs from ``evaluate`` by <= 0.011 N in S
and 0.013 N in F_d; values at cage speeds up to 1500 rad/s and the refresh slopes agree to
< 1e-3 N and < 0.5 %; the raceways' net orbital force there is strongly restoring
(sum F_d = -49 N at 1200 rad/s). Not the refresh interval (5 us: the same runaway), not the
grid (spin 25 rad/s, 32 load nodes, 1.25 % cage layers: no runaway at 420 and 370 K,
but an excursion to 1196 rad/s at 350 K). Not the step alone (800 steps per spin period: the cage
reaches 1050 rad/s at the end of 5 orbits; 380: the same stop). The evaluate path at the
same states stays in the band: 420 K cage 941-987 rad/s, 350 K 935-955, 410 K 948-983
(rib heat 18.7-19.7 W per roller); the table path at 350 / 370 / 410 / 420 K ran to 1200 /
1228 / (band) / 1840 rad/s (heat 75.7 / 33.2 W per roller where it finished): 4 of 13
table runs at 345-440 K, 0 of 3 evaluate runs here (D2: 0 of 5) -- not a resolved
difference (if both had the table's rate, 0 of 8 would happen with probability ~0.06).
And the two paths are the same dynamics: with the table's values fed through the Python
refresh of the evaluate path, the trajectory equals the in-kernel table path's exactly
for 0.12 ms, to the last bits for 0.3 ms, and then decorrelates from the last-bit
differences of the two refresh codes
(420 K: spin difference 1e-10 rad/s at 1.2 ms, 2e-3 at 2.4 ms, 130 at 4.3 ms: an e-folding
time of ~0.07 ms); that run did not enter the runaway within 21 ms, the kernel run did at
15 ms. So the runaway is a regime of the model's chaotic impacting motion (not of the
table), entered on some trajectories; whether it is physical (a roller can rattle between
ribs with 3x the others' penetration and hold ~300 N on its bar) is not settled. Handling:
the cage speed must stay within 1 +- :data:`DEFAULT_CAGE_BAND` of the quasi-static one
(checked at every table exit; the evaluate path's cage stayed within +11 %, paper 003's
base case within +3 %); a table-path run leaving it is re-run whole on the evaluate path
(~12-19 s CPU instead of ~2 s at 20000 r/min) and flagged (``series["traction_fallback"]``):
the re-run follows another trajectory, so its statistics are those of a run that did not
enter the runaway, and the flag says one was met;
an evaluate-path run leaving it raises ConvergenceError "unstable coupled motion" with the
state (no silent result). Test: ``tests/unit/test_roller_dynamics_coupled.py``.

Retries on the table path (2026-11-23, late; issue 9 cost). The evaluate-path re-run costs
6-25x a table run (3 ``evaluate`` calls from Python per 20 us refresh) and follows just
another trajectory of the same dynamics (above). ``table_retries`` = k first tries up to
k other trajectories on the table path -- the start's cage speed times 1 + j
:data:`TRAJECTORY_PERTURBATION` (1e-9; the motion decorrelates with an e-folding time of
~0.07 ms, so within ~1.5 ms of a 2-orbit warm-up) -- and only then the evaluate path. Same
conditioning as the evaluate re-run (a trajectory that did not enter the runaway), same
population, measured (2 + 3 orbits, MIL-PRF-23699, 3 kN, 0.06 g, both ribs):
20000 r/min at 420 K (the state above), table trajectories j = 0..9: 2 of 10 ran away
(within 0.6 s CPU), the other 8 rib heat 18.83-21.49 W per roller (mean 19.56, standard
error 0.31), slide 17.93-18.13 m/s, 1.1-1.2 s CPU each; evaluate path j = 0..2: 1 of 3 ran
away, 19.87 / 19.90 W, slide 18.04 / 18.06 m/s, 6.9-7.6 s CPU. 5000 r/min at 380 K: table
3 of 10 ran away, the other 7 0.362-0.472 W (mean 0.405), slide 4.938-4.960 m/s, 3.3-3.5 s
CPU; evaluate 1 of 2 ran away, 0.410 W, 4.955 m/s, 21.5 s CPU. The table path is also the
more accurate of the two where the spin is stiff ("Stiff spin": the evaluate path cannot
renew its linearisation inside the kernel). Default 0 here (callers keep their path); the
rib heat source uses 3 (:mod:`~thermobearing.skidding.roller_dynamics_heat`).

Unbalance mass's axial excursion (2026-11-24, issue 9; paper 003 eq. 18 line 1, F_cwx). The
unbalance enters the roller equations as the centrifugal force of a mass m_u at (x_u, e_u
cos psi, e_u sin psi) in roller axes (:mod:`~thermobearing.skidding.roller_dynamics_rhs`: skew
moment -x_u F sin psi, pocket force F sin psi, orbital force on the outer race). Eq. 18's
axial line carries the mass's axial force F_cwx too, which the model left out: a skewed
roller carries the mass's circumferential offset e_u sin psi to the axial position
e_u sin(psi) sin(alpha), so the geometric centre (where the rib and raceway contacts act)
moves axially against the mass -- up to k e_u sin(alpha) = 1.9 um at the 0.6 deg rib skew of
the base case (k = m_u/(m + m_u) = 0.076 at 0.11 g), of the size of the rib's Hertz approach
(~1 um at 100 N). The cage frame turns about the bearing axis, so its inertial forces have
no axial part and the axial momentum of roller + mass is exact: the state's X, X' are now
those of the centre of mass, (m + m_u) X_c'' = F_x, the contacts see X_G = X_c - k (r_x -
x_u) and its rate; the same forces act on the skew with the centre of mass's arm (-k r_z
F_x) and on the spin phase (-k dr_x/dpsi F_x), the virtual work of F_x on X_G
(:func:`~thermobearing.skidding.roller_dynamics_coupled_kernels.unbalance_axial_shift`;
samples and ``series["axial"]`` hold the geometric centre's X, X'; ``series["end_state"]``
the integrated state). The skew and pocket keep the rotating-force form (the mass's own
share of the skew inertia, ~15 % of J_t at 0.11 g, is not followed). The reduced and one-
roller models (roller_dynamics_integrate) do not have the term. Measured (base case,
MIL-PRF-23699, 80 degC, 2 + 3 orbits, 8 trajectories per mass at 384 ... 440 steps per spin
period; validation case SOURCE.md "Unbalance mass's axial excursion"): at C_a = 0.03 mm
right/left PV 1.001 +- 0.005 -> 0.998 +- 0.003 at 0.11 g, contact fractions left / right
0.104 / 0.104 -> 0.106 / 0.107; at 0.01 mm right/left 1.02 -> 1.09 (contact 0.221 / 0.230
-> 0.214 / 0.253: the unbalance side touches more where the rib is close); slip at 0.11 g
4.86 -> 4.65 m/s (0.01 mm 3.07 -> 2.86, 0.05 mm 5.51 -> 5.45), PV within the scatter.
"""

from __future__ import annotations

import math
import time
from dataclasses import replace
from typing import Any

import numpy as np

from ..errors import ConvergenceError, InputError, check_positive
from .roller_dynamics_convergence import (
    BLOCKS_PER_ORBIT,
    DEFAULT_SETTLE,
    HEAT_FLOOR,
    MIN_BLOCKS,
    SETTLE_MAX_ORBITS,
    SLIDE_FLOOR,
    block_heat_slide,
    cage_mode_ratio,
    creep_settled,
    window_converged,
)
from .roller_dynamics_coupled_kernels import (  # noqa: F401  (kernels re-exported)
    N_ROLLER_STATES,
    _deriv_into,
    _integrate,
    _interp_sorted,
    _pocket_film_friction,
    _refresh_from_table,
    _refresh_roller,
    _stiff_rates,
    _stiff_roller,
    pocket_damping,
    spin_pocket_coupling,
    unbalance_axial_shift,
)
from .roller_dynamics_model import DynamicsModel
from .roller_dynamics_response import RollerResponse, _post, _response
from .roller_dynamics_rhs import _params
from .roller_dynamics_table import DEFAULT_CAGE_STEP, build_traction_table
from .roller_dynamics_tilt import N_TILT_STATES, start_states, tilt_parameters

#: band of the cage speed around the quasi-static one, as a fraction (simulate_coupled):
#: evaluate-path runs stay within +11 % (20000 r/min, 420 K, 0.06 g: 886 -> <= 987 rad/s),
#: +3 % at paper 003's base case; the table path's runaways reach +30 % and beyond
DEFAULT_CAGE_BAND = 0.2
#: time integrators of simulate_coupled (module notes, "Stiff spin"): "etd" (default,
#: ETDRK4 with the spin relaxation exact) or "rk4" (classical RK4, explicit throughout)
INTEGRATORS = ("etd", "rk4")
#: table (re)builds after which the table path is given up (simulate_coupled)
MAX_TABLE_BUILDS = 20


def cage_inertia(bearing: Any) -> tuple[float, float, dict[str, str]]:
    """(mass [kg], polar moment of inertia [kg m^2], estimated-fields note) of the cage.

    The cage's own ``mass`` if given; else a ring of the cage's inner/outer diameter and
    width with Z pockets of D x L_r through its radial wall removed, density of its material
    (estimated). J_c = m (r_o^2 + r_i^2) / 2 (thick ring).
    """
    cage = bearing.cage
    r_o, r_i = 0.5 * cage.outer_diameter, 0.5 * cage.inner_diameter
    note = {}
    mass = getattr(cage, "mass", None)
    if not mass:
        ring = math.pi * (r_o**2 - r_i**2) * cage.width
        pockets = bearing.n_rollers * bearing.roller_diameter * bearing.roller_length * (
            r_o - r_i)
        mass = cage.material.density * (ring - pockets)
        note["cage_mass"] = ("ring of the cage diameters and width minus Z pockets D x L_r "
                             "through the wall, cage material density (estimated)")
    return float(mass), float(0.5 * mass * (r_o**2 + r_i**2)), note


def inner_ring_mass(bearing: Any) -> tuple[float, dict[str, str]]:
    """(mass [kg], estimated-fields note) of the inner ring for its axial DOF (paper 003
    eq. 20 line 1): a ring of the bore and the inner raceway diameter over the bearing
    width, ring material density (estimated: ribs and chamfers ignored, ~10 %)."""
    r_o, r_i = 0.5 * bearing.inner_raceway_diameter, 0.5 * bearing.bore
    mass = bearing.ring_material.density * math.pi * (r_o**2 - r_i**2) * bearing.width
    return float(mass), {"inner_ring_mass": "bore x inner raceway diameter x width annulus, "
                                             "ring material density (estimated)"}


def cage_land_coefficient(bearing: Any, m: DynamicsModel) -> tuple[float, float]:
    """(k [N m s], omega_g [rad/s]) of the cage-land drag torque k (omega_g - omega_c).

    Paper 003 eq. 19 line 3 has the friction moment M'_cx of the guide-land film of its
    inner-ring-guided cage (expression in its ref. [26], not given); here the concentric
    Petroff torque of :func:`thermobearing.heat_sources.cage_guide.land_drag_torque` (paper
    002 eq. 5), pi eta D_g^3 B_c / (4 c), with c = guide_clearance / 2 and eta the oil/air
    mixture viscosity of the rib gap (``m.mixture_viscosity``, the same estimated oil
    fraction as eq. 14's drag). omega_g = omega_i for an inner-ring-guided cage, 0 for an
    outer-ring-guided one; (0, 0) for a roller-guided cage.
    """
    from ..heat_sources.cage_guide import land_drag_torque

    cage = bearing.cage
    if cage.guidance not in ("inner_ring", "outer_ring") or not cage.guide_land_diameter:
        return 0.0, 0.0
    k = land_drag_torque(m.mixture_viscosity, cage.guide_land_diameter, 1.0, 0.0,
                         cage.land_width, 0.5 * cage.guide_clearance, 0.0)
    return float(k), float(m.inner_speed if cage.guidance == "inner_ring" else 0.0)




#: a roller spin above this multiple of omega_i d_i / D (the spin of a roller rolling on the
#: inner raceway with the cage at rest, the most any raceway traction drives) is a runaway
#: of the integration, not motion: the table path stops instead of spanning it
SPIN_RUNAWAY = 2.0


#: on the table path of the "etd" integrator a roller's traction linearisation is renewed
#: as soon as its spin moved by more than this fraction of the table's spin step from the
#: spin it was linearised at (module notes, "Stiff spin")
SPIN_TRUST = 0.25


#: relative perturbation of the start's cage speed per table retry (simulate_coupled)
TRAJECTORY_PERTURBATION = 1e-9


class _TableCannotFollow(Exception):
    """The table path's state left the cage band (or the table kept being left):
    :func:`simulate_coupled` re-runs the reference path."""

    def __init__(self, reason: str, state: dict[str, Any]) -> None:
        super().__init__(reason)
        self.reason = reason
        self.state = state


def simulate_coupled(m: DynamicsModel, bearing: Any, lubricant: Any, *,
                     n_orbits: float = 2.0, warmup_orbits: float = 2.0,
                     refresh: float = 20e-6, steps_per_period: int = 400,
                     samples_per_period: int = 100, phase_spread: bool = True,
                     traction: str = "table", table_options: dict[str, Any] | None = None,
                     ring_axial: bool = False, cage_land: bool = False,
                     cage_band: float | None = DEFAULT_CAGE_BAND,
                     fallback: bool = True, integrator: str = "etd",
                     converge: float | None = None, table_retries: int = 0,
                     settle: float | None = None,
                     settle_max_orbits: float = SETTLE_MAX_ORBITS,
                     start: np.ndarray | None = None) -> RollerResponse:
    """Integrate all Z rollers and the cage together (module notes) from the coupled
    quasi-static state of ``m`` (:func:`~thermobearing.skidding.roller_dynamics.build_model`),
    ``warmup_orbits`` discarded, statistics over the next ``n_orbits`` cage orbits.

    ``refresh`` [s]: interval of the raceway-traction linearisation. ``phase_spread``: the
    rollers' unbalance phases spread by the golden angle (True) or all equal (False).
    ``traction``: where the linearisation comes from -- "table" (default: paper 000's
    traction model tabulated once per run and interpolated inside the jitted time loop,
    :mod:`~thermobearing.skidding.roller_dynamics_table`; ``table_options`` its grid
    keywords) or "evaluate" (three calls of
    :func:`thermobearing.skidding.roller_residual.evaluate` per refresh from Python, the
    reference the table is checked against; ~6x slower). Both run the same jitted loop.
    ``integrator``: "etd" (default: ETDRK4 with the spin relaxation exact and, on the table
    path, a roller's linearisation renewed when its spin moved by :data:`SPIN_TRUST` table
    spin steps; module notes, "Stiff spin") or "rk4" (the previous explicit scheme, which
    diverges with mineral oils).
    ``ring_axial``: the inner ring free to move axially under the rib and inner-raceway
    axial forces of all rollers (paper 003 eq. 20 line 1, no external axial load; mass
    :func:`inner_ring_mass`) instead of held by the shaft (default).
    ``cage_land``: add the viscous drag torque of the cage's guide land (paper 003 eq. 19
    line 3, M'_cx; :func:`cage_land_coefficient`) to the cage equation (default off: the
    quasi-static start state, paper 000's model, has none).
    ``converge``: None (default) -- the fixed window (``warmup_orbits`` discarded, then
    ``n_orbits``); a relative tolerance (0, 1) -- stop as soon as the running means of the
    roller-mean rib heat and rib slide speed have converged to it, the statistics window the
    later half of the motion so far
    (:mod:`~thermobearing.skidding.roller_dynamics_convergence`), at most the fixed window's
    length; a run that never converges returns the fixed window's result exactly (same
    trajectory and samples). ``series["converged"]`` = [1] / [0], ``series["window"]`` =
    [start, end] of the statistics window [s], ``series["simulated_orbits"]`` the orbits
    integrated (of the quasi-static cage speed).
    ``settle``: None (default) -- the fixed warm-up; a relative tolerance (0, 1) -- warm up
    in whole cage orbits (at least max(2, ceil(``warmup_orbits``)); 2 with ``converge``,
    whose running-mean test then starts with the last warm-up orbit) until the orbit-mean
    cage speed changes by at most ``settle`` from one orbit to the next, with no turning
    point and the extrapolated remainder of its creep at most ``settle``
    (:func:`~thermobearing.skidding.roller_dynamics_convergence.creep_settled`), at most
    ``settle_max_orbits`` warm-up orbits (module notes, "Cage settling", "Settling test").
    ``series["settled"]`` = [1] if the test passed (else [0]), ``series["warmup_orbits"]``
    the orbits before the statistics window, ``series["settle_ratio_floor"]`` the cage
    mode's decay ratio over half an orbit at the last test (NaN without ``settle``).
    ``start``: None (default) -- the quasi-static state of ``m``; a previous run's
    ``series["end_state"]`` (the integrated state at its end, (Z x 8 + 4,): the rollers' X,
    X', alpha, alpha', z, z', psi, omega, then cage angle and speed, ring X and X') of the
    same bearing, e.g. at a neighbouring temperature (module notes, "Cage settling"); a
    wrong size or a non-finite value raises InputError.
    ``table_retries``: before the evaluate-path re-run below, up to this many other
    trajectories on the table path (the start's cage speed times 1 + k
    :data:`TRAJECTORY_PERTURBATION`, k = 1, 2, ...; module notes, "Retries on the table
    path"); ``series["table_retries"]`` the retries a result needed (default 0: none),
    ``series["fallback_traction"]`` the path that finished ("table" / "evaluate").
    Returns a :class:`~thermobearing.skidding.roller_dynamics.RollerResponse` (``model`` =
    "coupled", means over all rollers and the time) whose ``series`` holds ``t`` [s],
    ``cage_speed`` [rad/s] and, as (time x Z) arrays, ``spin`` [rad/s], ``axial`` X [m],
    ``skew`` alpha [rad], ``pocket`` z [m], ``axial_speed`` X' [m/s] and ``skew_rate``
    alpha' [rad/s], ``pocket_speed`` z' [m/s] (X, X' relative to the inner ring), and
    ``ring_axial``, the inner ring's axial position [m]. ``cost_s``: CPU seconds.
    ConvergenceError if the state becomes non-finite or a spin reverses.

    ``cage_band`` [-]: the cage speed must stay within (1 +- cage_band) times the
    quasi-static cage speed ``m.cage_speed`` (default :data:`DEFAULT_CAGE_BAND`; None: no
    check). On the table path a cage outside the band, or a table left more than
    :data:`MAX_TABLE_BUILDS` times, stops the run; with ``fallback`` (default) the whole run
    is then repeated on the ``"evaluate"`` path (the reference) and the result says so:
    ``series["traction_fallback"]`` = [1] (else [0]), ``series["fallback_cage_speed"]`` the
    table path's cage speed [rad/s] and ``series["fallback_time"]`` its time [s] when it
    stopped. What this is (module notes, "Cage runaway"): a cage-overspeed runaway of the
    motion itself (one roller rattling between its ribs), entered on some trajectories of
    the chaotic motion; the re-run follows another trajectory (the paths decorrelate within
    ~1 ms), so a fallback result is the statistics of a run that did not enter it, and the
    flag says that a runaway was met. On the evaluate path (or without ``fallback``) a cage
    outside the band raises ConvergenceError "unstable coupled motion" with the state
    (time, cage speed, the roller deepest in its ribs).
    """
    if table_retries < 0:
        raise InputError("table_retries", table_retries, "a count >= 0")
    kwargs = dict(n_orbits=n_orbits, warmup_orbits=warmup_orbits, refresh=refresh,
                  steps_per_period=steps_per_period, samples_per_period=samples_per_period,
                  phase_spread=phase_spread, table_options=table_options,
                  ring_axial=ring_axial, cage_land=cage_land, cage_band=cage_band,
                  integrator=integrator, converge=converge, settle=settle,
                  settle_max_orbits=settle_max_orbits, start=start)
    t0 = time.process_time()
    try:
        return _simulate_coupled_path(m, bearing, lubricant, traction=traction, **kwargs)
    except _TableCannotFollow as stop:
        if not fallback:
            raise ConvergenceError(
                "roller_dynamics.coupled", float(stop.state.get("cage_ratio", float("inf"))),
                f"unstable coupled motion on the table path ({stop.reason}; a cage runaway "
                f"of the motion, module notes) and fallback=False",
                stop.state) from None
        resp, retries, finished = None, 0, "table"
        if traction == "table":
            for k in range(1, table_retries + 1):
                retries = k
                try:
                    resp = _simulate_coupled_path(m, bearing, lubricant, traction="table",
                                                  trajectory=k, **kwargs)
                    break
                except _TableCannotFollow:
                    continue
        if resp is None:
            finished = "evaluate"
            resp = _simulate_coupled_path(m, bearing, lubricant, traction="evaluate",
                                          **kwargs)
        series = dict(resp.series)
        series["table_retries"] = np.array([retries])
        series["fallback_traction"] = np.array([finished])
        series["traction_fallback"] = np.array([1])
        series["fallback_cage_speed"] = np.array([stop.state["cage_speed"]])
        series["fallback_time"] = np.array([stop.state["t"]])
        return replace(resp, series=series, cost_s=time.process_time() - t0)


def _unbalance_constants(m: DynamicsModel) -> tuple[float, float, float, float]:
    """(k = m_u/(m + m_u) [-], e_u [m], x_u [m], m_u [kg]) of the unbalance's axial
    excursion (:func:`~thermobearing.skidding.roller_dynamics_coupled_kernels.
    unbalance_axial_shift`); zeros without unbalance."""
    u = m.unbalance
    if u.mass <= 0.0:
        return 0.0, 0.0, 0.0, 0.0
    return (u.mass / (m.roller_mass + u.mass), u.radius, u.axial_position, u.mass)


def _simulate_coupled_path(m: DynamicsModel, bearing: Any, lubricant: Any, *,
                           n_orbits: float, warmup_orbits: float, refresh: float,
                           steps_per_period: int, samples_per_period: int,
                           phase_spread: bool, traction: str,
                           table_options: dict[str, Any] | None, ring_axial: bool,
                           cage_land: bool, cage_band: float | None,
                           integrator: str, converge: float | None = None,
                           trajectory: int = 0, settle: float | None = None,
                           settle_max_orbits: float = SETTLE_MAX_ORBITS,
                           start: np.ndarray | None = None) -> RollerResponse:
    """One run of :func:`simulate_coupled` on one traction path (arguments as there);
    raises :class:`_TableCannotFollow` on the table path, ConvergenceError on the
    evaluate path when the cage leaves ``cage_band``."""
    from .roller import build_model as race_model
    from .roller_dynamics_coupling import _race_eval_at, unbalance_orbital_force
    from .roller_fluid import martin_coefficients

    check_positive("refresh", refresh)
    if traction not in ("table", "evaluate"):
        raise InputError("traction", traction, ("table", "evaluate"))
    if integrator not in INTEGRATORS:
        raise InputError("integrator", integrator, INTEGRATORS)
    if converge is not None and not 0.0 < converge < 1.0:
        raise InputError("converge", converge, "None or a relative tolerance in (0, 1)")
    if settle is not None:
        if not 0.0 < settle < 1.0:
            raise InputError("settle", settle, "None or a relative tolerance in (0, 1)")
        check_positive("settle_max_orbits", settle_max_orbits)
    t0 = time.process_time()
    rm = race_model(bearing, lubricant, m.extras.get("temperature", 353.15))
    z_n = len(m.azimuth)
    n = N_ROLLER_STATES
    half = 0.5 * m.geom.roller_diameter
    c = _params(m)
    _, j_c, _ = cage_inertia(bearing)
    k_w, k_q, k_c, _ = martin_coefficients()
    film = np.array([m.pocket_length, m.pocket_viscosity, m.pocket_clearance, k_w,
                     k_c + 0.5 * k_q, 1e-4])
    consts = np.array([m.polar_inertia, j_c, half, 0.5 * m.geom.pitch_diameter,
                       float(rm.cage_drag_torque),
                       inner_ring_mass(bearing)[0] if ring_axial else 0.0,
                       *(cage_land_coefficient(bearing, m) if cage_land else (0.0, 0.0)),
                       *_unbalance_constants(m)])
    az = np.append(m.azimuth, m.azimuth[0] + 2.0 * math.pi)
    load = np.append(m.inner_load, m.inner_load[0])
    phi0 = m.azimuth.copy()
    tilt = bool(getattr(m, "tilt", False))
    if tilt:
        tp, gap = tilt_parameters(m, bearing)
    else:
        tp, gap = np.zeros(1), np.zeros(1)
    # rollers, cage angle and speed, ring X and X' (then, with tilt, each roller's y_r, y_r',
    # alpha_e, alpha_e': roller_dynamics_tilt)
    y = np.zeros(z_n * n + 4 + (N_TILT_STATES * z_n if tilt else 0))
    if tilt:
        y[z_n * n + 4:] = start_states(m, tp, gap).ravel()
    golden = math.pi * (3.0 - math.sqrt(5.0))
    for j in range(z_n):
        b = j * n
        f_d = float(m.pocket_force[j]) if m.pocket_force is not None else 0.0
        y[b + 4] = math.copysign(0.5 * m.pocket_clearance, f_d) if m.pocket_dof else 0.0
        y[b + 6] = golden * j if phase_spread else 0.0
        y[b + 7] = m.spin[j]
    # another trajectory of the chaotic motion (table retries): the start's cage speed
    # perturbed at the 1e-9 level, decorrelated within ~1.5 ms (e-folding ~0.07 ms)
    y[z_n * n + 1] = m.cage_speed
    if start is not None:
        # a previous run's end state (series["end_state"]) of the same bearing: the rollers'
        # states, the cage angle (within its first turn) and speed, the ring's axial state
        y0 = np.asarray(start, float)
        if y0.shape != y.shape or not np.all(np.isfinite(y0)):
            raise InputError("start", f"{y0.shape} values",
                             f"{y.size} finite values (a previous run's series['end_state'] "
                             f"of this bearing, {z_n} rollers)")
        y[:] = y0
        y[z_n * n] = math.fmod(y0[z_n * n], 2.0 * math.pi)
    y[z_n * n + 1] *= 1.0 + TRAJECTORY_PERTURBATION * trajectory
    omega_rib = math.sqrt(1.5 * m.geom.stiffness * math.sqrt(20e-6) / m.roller_mass)
    period = 2.0 * math.pi / max(float(np.max(m.spin)), 1.0)
    h = min(period / steps_per_period, 1.0 / omega_rib)
    sub = max(1, int(round(refresh / h)))
    orbit = 2.0 * math.pi / m.cage_speed
    if settle is not None:
        # whole warm-up orbits, at least two (the test compares two orbit means); with
        # ``converge`` the settling warm-up comes first and the running-mean test starts
        # after it (its blocks and window from the settled state on)
        warmup_orbits = (max(2.0, float(math.ceil(warmup_orbits))) if converge is None
                         else 2.0)
        settle_max_orbits = max(settle_max_orbits, warmup_orbits)
    n_warm = int(math.ceil(warmup_orbits * orbit / h))
    n_keep = int(math.ceil(n_orbits * orbit / h))
    n_total = n_warm + n_keep
    every = max(1, int(period / samples_per_period / h))
    # with ``converge`` the samples start at the first step of the fixed window's sample
    # grid (n_warm mod every), so that the fixed window's samples are among them
    s_first = n_warm if converge is None else n_warm % every
    n_alloc = n_total
    if settle is not None and converge is not None:
        # the settling warm-up is sampled too (its last orbit opens the running-mean test)
        n_alloc = int(math.ceil((settle_max_orbits + 1.0) * orbit / h)) + n_keep
    n_samples = (n_alloc - s_first + every - 1) // every
    # test blocks of 1/BLOCKS_PER_ORBIT orbit, whole refresh intervals (the evaluate path
    # refreshes at every kernel call: its trajectory is then that of the fixed window)
    n_block = (sub * max(1, int(round(orbit / BLOCKS_PER_ORBIT / h / sub))) if converge
               else n_total)
    next_check = min(n_block, n_total)
    blocks: list[tuple[float, float]] = []
    checked = 0                        # samples already in a block
    window0 = n_warm                   # first step of the statistics window
    converged = False
    # warm-up settling (settle): (t, cage angle) at each warm-up half orbit's end
    marks = [(0.0, float(y[z_n * n]))]
    settling = settle is not None
    settled = 0
    settle_floor = math.nan            # cage_mode_ratio at the last settling test
    base = 0                           # first step of the running-mean test's blocks
    if settling:
        next_check = min(int(math.ceil(0.5 * orbit / h)), n_total)
    samples = np.zeros((n_samples, z_n * n))
    sample_t = np.zeros(n_samples)
    sample_wc = np.zeros(n_samples)
    sample_ring = np.zeros(n_samples)
    sample_tilt = np.zeros((n_samples if tilt else 1, z_n, 2))
    lin = np.zeros((z_n, 7))
    w0 = np.zeros(z_n)
    q_o = np.zeros(z_n)
    c_z = np.zeros(z_n)
    wc0 = 0.0
    n_eval = 0
    tables = []
    reasons: list[int] = []
    opts = dict(table_options or {})

    step_c = opts.pop("cage_step", DEFAULT_CAGE_STEP)
    # cage layers -2 .. 4: the Catmull-Rom in the cage speed is defined on -1 .. 3
    span = {"w_lo": 0.8 * float(np.min(m.spin)), "w_hi": 0.0, "k_lo": -2, "k_hi": 4}

    def new_table(spins: np.ndarray, wc: float) -> Any:
        """(Re)build the table over the spins and cage speeds seen so far (a grid left is
        extended, never shifted, so an oscillating state does not rebuild it again)."""
        k = (wc / m.cage_speed - 1.0) / step_c
        span["k_lo"] = min(span["k_lo"], int(math.floor(k)) - 2)
        span["k_hi"] = max(span["k_hi"], int(math.ceil(k)) + 2)
        wc_lo = m.cage_speed * (1.0 + step_c * span["k_lo"])
        w_roll = ((m.inner_speed - max(wc_lo, 0.0)) * m.geom.inner_raceway_diameter
                  / m.geom.roller_diameter)
        span["w_lo"] = min(span["w_lo"], 0.8 * float(np.min(spins)))
        span["w_hi"] = max(span["w_hi"], 1.05 * w_roll, 1.05 * float(np.max(spins)))
        tab = build_traction_table(rm, m.inner_speed,
                                   lambda wc_: unbalance_orbital_force(m, wc_),
                                   (span["w_lo"], span["w_hi"]), float(np.max(m.inner_load)),
                                   m.cage_speed, cage_step=step_c,
                                   cage_layers=(span["k_lo"], span["k_hi"]),
                                   previous=tables[-1] if tables else None, **opts)
        tables.append(tab)
        return tab

    empty = np.zeros(1)
    tab = (new_table(np.append(m.spin, y[7::n][:z_n]), float(y[z_n * n + 1]))
           if traction == "table" else None)
    t = 0.0
    step = 0
    n_sampled = 0
    while step < n_total:
        if tab is None:
            if not np.all(np.isfinite(y)):
                # the integrator checks every 200 steps, a refresh may come first: its
                # evaluation would stop on the NaN loads ("load = array([nan, ...])")
                raise ConvergenceError("roller_dynamics.coupled", float("inf"),
                                       "state not finite", {"t": t, "step": step})
            # reference path: the linearisation from three evaluate calls per refresh
            w0 = y[7::n][:z_n].copy()
            wc0 = float(y[z_n * n + 1])
            phi = np.mod(phi0 + y[z_n * n], 2.0 * math.pi)
            n_i = np.interp(phi, az, load)
            dw = 1e-4 * np.maximum(np.abs(w0), 1.0)
            dc = 1e-4 * max(abs(wc0), 1.0)
            e0 = _race_eval_at(rm, m, w0, wc0, n_i, phi)
            e1 = _race_eval_at(rm, m, w0 + dw, wc0, n_i, phi)
            e2 = _race_eval_at(rm, m, w0, wc0 + dc, n_i, phi)
            n_eval += 3
            s0 = e0.roller_eq + e0.friction
            lin[:, 0] = s0
            lin[:, 1] = (e1.roller_eq + e1.friction - s0) / dw
            lin[:, 2] = (e2.roller_eq + e2.friction - s0) / dc
            lin[:, 3] = e0.pocket
            lin[:, 4] = (e1.pocket - e0.pocket) / dw
            lin[:, 5] = (e2.pocket - e0.pocket) / dc
            q_o = np.asarray(e0.q_o, float).copy()
            c_z = np.array([pocket_damping(float(k), half) for k in lin[:, 1]])
            ko = (e1.outer.shear_force - e0.outer.shear_force) / dw
            lin[:, 6] = [spin_pocket_coupling(float(k), float(o), half)
                         for k, o in zip(lin[:, 1], ko, strict=True)]
            block = min(sub, next_check - step)
            grid = (0.0, 1.0, empty, empty, np.zeros((1, 1, 1, 3)))
        else:
            block = next_check - step
            grid = (tab.spin0, tab.spin_step, tab.loads, tab.cage, tab.values)
        status, done, t, n_sampled, wc0 = _integrate(
            c, y, t, step, block, h, sub, z_n, phi0, az, load, lin, w0, wc0, q_o, c_z,
            consts, film, tab is not None, *grid, s_first, every, samples, sample_t,
            sample_wc, sample_ring, n_sampled, integrator == "etd",
            SPIN_TRUST * grid[1] if integrator == "etd" and tab is not None else 0.0,
            tp, gap, sample_tilt)
        step += done
        if status == 4:
            raise ConvergenceError("roller_dynamics.coupled", float("inf"),
                                   "state not finite or a roller spin reversed",
                                   {"t": t, "step": step})
        wc_now = float(y[z_n * n + 1])
        ratio = wc_now / m.cage_speed
        if cage_band is not None and abs(ratio - 1.0) > cage_band:
            state = _unstable_state(m, y, z_n, t, step, wc_now, traction)
            if tab is not None:
                raise _TableCannotFollow(f"cage speed {wc_now:.1f} rad/s outside "
                                         f"1 +- {cage_band} x quasi-static", state)
            raise ConvergenceError(
                "roller_dynamics.coupled", abs(ratio - 1.0),
                f"unstable coupled motion: the cage speed ran to {wc_now:.1f} rad/s, "
                f"{ratio:.3f} x the quasi-static {m.cage_speed:.1f} rad/s (band 1 +- "
                f"{cage_band}) on the evaluate (reference) traction path; roller "
                f"{state['roller']} deepest in its ribs (|X| = {state['roller_axial']:.2e} m, "
                f"pocket z = {state['roller_pocket']:.2e} m)", state)
        if status != 0:
            if len(tables) > MAX_TABLE_BUILDS:
                raise _TableCannotFollow(
                    f"the state left the traction table {len(tables)} times",
                    _unstable_state(m, y, z_n, t, step, wc_now, traction))
            reasons.append(int(status))
            spins = y[7::n][:z_n]
            w_drive = (m.inner_speed * m.geom.inner_raceway_diameter
                       / m.geom.roller_diameter)
            top = float(np.max(np.abs(spins)))
            if not top <= SPIN_RUNAWAY * w_drive:
                # the table would span the runaway spin on its fixed spin step (a 40 degC
                # ISO VG46 case at 5000 r/min asked for 3.9e6 nodes, 10.9 GiB)
                raise _TableCannotFollow(
                    f"a roller spin ran to {top:.3g} rad/s, beyond {SPIN_RUNAWAY:g} x the "
                    f"{w_drive:.1f} rad/s the inner raceway drives with the cage at rest",
                    _unstable_state(m, y, z_n, t, step, wc_now, traction))
            tab = new_table(spins, wc_now)
        if settling and status == 0 and step == next_check:
            # a warm-up half orbit done; at a whole orbit: settled when the orbit-mean cage
            # speeds over the last two orbits and the orbit between them pass
            # creep_settled (no turning point, the geometric creep's remainder <= settle);
            # else warm up one more orbit, at most settle_max_orbits (module notes, "Cage
            # settling")
            marks.append((t, float(y[z_n * n])))
            k = (len(marks) - 1) // 2          # whole warm-up orbits done
            if (len(marks) - 1) % 2 == 1:
                next_check = min(int(math.ceil((k + 1) * orbit / h)), n_total)
                continue
            if step >= n_warm:
                w_a, w_b, w_c = (_orbit_mean(marks[-5 + i], marks[-3 + i]) for i in (0, 1, 2))
                # the cage mode's decay over half an orbit from the linearisation now
                settle_floor = cage_mode_ratio(float(np.sum(lin[:, 5])), j_c, m.roller_mass,
                                               z_n, 0.5 * m.geom.pitch_diameter,
                                               0.5 * (marks[-1][0] - marks[-3][0]))
                if creep_settled(w_a, w_b, w_c, settle, settle_floor):
                    settling, settled = False, 1
                elif k + 1 > settle_max_orbits + 1e-9:
                    settling = False
                else:
                    grow = int(math.ceil((k + 1) * orbit / h)) - n_warm
                    n_warm += grow
                    n_total += grow
                    if converge is None:
                        s_first = n_warm
                        window0 = n_warm
            if settling:
                next_check = min(int(math.ceil((k + 0.5) * orbit / h)), n_total)
            elif converge is None:
                next_check = n_total
            else:
                # the running-mean test from the last warm-up orbit on (the one the settling
                # test passed on), at most the statistics orbits from there; its blocks
                # over that orbit are taken from the samples already there
                base = window0 = int(math.ceil((k - 1) * orbit / h))
                n_total = max(base + n_keep, step)
                checked = _samples_before(base, s_first, every, n_sampled)
                nxt = base + n_block
                while nxt <= step:
                    i1 = _samples_before(nxt, s_first, every, n_sampled)
                    blocks.append(block_heat_slide(
                        m, samples[checked:i1].reshape(i1 - checked, z_n, n),
                        sample_wc[checked:i1]) if i1 > checked else (math.nan, math.nan))
                    checked = i1
                    nxt += n_block
                next_check = min(nxt, n_total)
                if _blocks_converged(blocks, converge):
                    converged = True
                    window0 = base + (len(blocks) // 2) * n_block
                    break
            continue
        if status == 0 and step == next_check and step < n_total:
            # one more block of the running-mean test (converge)
            blk = samples[checked:n_sampled].reshape(n_sampled - checked, z_n, n)
            blocks.append(block_heat_slide(m, blk, sample_wc[checked:n_sampled])
                          if n_sampled > checked else (math.nan, math.nan))
            checked = n_sampled
            if _blocks_converged(blocks, converge):
                converged = True
                window0 = base + (len(blocks) // 2) * n_block
                break
            next_check = min(next_check + n_block, n_total)
    # the statistics window's samples (fixed window: from step n_warm on)
    i0 = max(0, -(-(window0 - s_first) // every))
    traj = samples[i0:n_sampled].reshape(n_sampled - i0, z_n, n)       # (time, Z, 8)
    tt = sample_t[i0:n_sampled]
    wc_t = sample_wc[i0:n_sampled]
    n_sampled -= i0
    mm = replace(m, cage_speed=float(np.mean(wc_t)))
    weights = []
    for j in range(z_n):
        r = traj[:, j, :]
        f_d = float(m.pocket_force[j]) if m.pocket_force is not None else 0.0
        weights.append((1.0 / z_n, _post(mm, tt, r[:, 0], r[:, 1], r[:, 2], r[:, 3],
                                         r[:, 7], r[:, 4], r[:, 5], f_d)))
    cost = time.process_time() - t0
    resp = _response(weights[0][1], "coupled", cost, 4 * step, m.geom, weights)
    n_table = sum(tb.evaluations for tb in tables)
    return replace(resp, series={"t": tt, "cage_speed": wc_t, "spin": traj[:, :, 7],
                                 "axial": traj[:, :, 0], "skew": traj[:, :, 2],
                                 "pocket": traj[:, :, 4],
                                 "axial_speed": traj[:, :, 1], "skew_rate": traj[:, :, 3],
                                 "pocket_speed": traj[:, :, 5],
                                 "ring_axial": sample_ring[i0:i0 + n_sampled].copy(),
                                 "traction_evaluations": np.array([n_eval]),
                                 "table_points": np.array([n_table]),
                                 "table_builds": np.array([len(tables)]),
                                 "table_rebuild_status": np.array(reasons, dtype=int),
                                 "step": np.array([h]), "refresh_steps": np.array([sub]),
                                 "integrator": np.array([integrator]),
                                 "traction_fallback": np.array([0]),
                                 "table_retries": np.array([0]),
                                 "converged": np.array([int(converged)]),
                                 "settled": np.array([settled]),
                                 "settle_ratio_floor": np.array([settle_floor]),
                                 "warmup_orbits": np.array([window0 * h / orbit]),
                                 "window": np.array([window0 * h, step * h]),
                                 "simulated_orbits": np.array([step * h / orbit]),
                                 "end_state": y.copy(),
                                 **({"radial": sample_tilt[i0:i0 + n_sampled, :, 0].copy(),
                                     "tilt": sample_tilt[i0:i0 + n_sampled, :, 1].copy()}
                                    if tilt else {})})


def _orbit_mean(first: tuple[float, float], last: tuple[float, float]) -> float:
    """Mean cage speed [rad/s] between two (t [s], cage angle [rad]) marks."""
    return (last[1] - first[1]) / (last[0] - first[0])


def _samples_before(step: int, s_first: int, every: int, n_sampled: int) -> int:
    """Samples taken at the steps before ``step`` (one every ``every`` steps from step
    ``s_first`` on, ``n_sampled`` so far)."""
    return min(n_sampled, max(0, -(-(step - s_first) // every)))


def _blocks_converged(blocks: list[tuple[float, float]], tol: float) -> bool:
    """The running-mean test (roller_dynamics_convergence) on the (heat, slide) block means
    so far: at least MIN_BLOCKS blocks, the later half of them converged to ``tol``."""
    nb = len(blocks)
    if nb < MIN_BLOCKS:
        return False
    win = np.array(blocks[nb // 2:])
    return (window_converged(win[:, 0], tol, HEAT_FLOOR)
            and window_converged(win[:, 1], tol, SLIDE_FLOOR))


def _unstable_state(m: DynamicsModel, y: np.ndarray, z_n: int, t: float, step: int,
                    wc: float, traction: str) -> dict[str, Any]:
    """State for the messages of :func:`simulate_coupled`: time [s], step, cage speed
    [rad/s] and its ratio to the quasi-static one, the roller deepest in its ribs (largest
    |X - X_ring|) with its X [m], pocket position z [m] and spin [rad/s], the mean spin."""
    n = N_ROLLER_STATES
    unb = np.array(_unbalance_constants(m))
    # the geometric centre's X (the state's is the centre of mass of roller + unbalance mass)
    x = np.array([y[i * n] - unbalance_axial_shift(unb, y[i * n + 2], y[i * n + 3],
                                                   y[i * n + 6], y[i * n + 7])[0]
                  for i in range(z_n)]) - y[z_n * n + 2]
    j = int(np.argmax(np.abs(x)))
    return {"t": float(t), "step": int(step), "traction": traction, "cage_speed": wc,
            "cage_ratio": wc / m.cage_speed, "roller": j, "roller_axial": float(x[j]),
            "roller_pocket": float(y[j * n + 4]), "roller_spin": float(y[j * n + 7]),
            "mean_spin": float(np.mean(y[7:z_n * n:n]))}


__all__ = ["DEFAULT_CAGE_BAND", "DEFAULT_SETTLE", "INTEGRATORS", "MAX_TABLE_BUILDS",
           "N_ROLLER_STATES", "SETTLE_MAX_ORBITS", "SPIN_TRUST", "TRAJECTORY_PERTURBATION",
           "cage_inertia", "cage_land_coefficient", "inner_ring_mass", "simulate_coupled"]
