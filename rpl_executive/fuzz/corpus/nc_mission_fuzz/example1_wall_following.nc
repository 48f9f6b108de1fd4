; Noreils and Chatila, section 6.2.1, Example 1: wall following. The MISSION form is the
; paper's, with these typographic normalizations (README "The paper's missions as files"):
;   - smooth-move(...) elides its path: it is smooth-move(PATH1), PATH1 defined below;
;   - the math of (ρ, θ) and (x, y, φ) is written in plain UTF-8 (the printed $\rho, \theta$);
;     the six symbols are variables defined below with values for the world hilare_room;
;   - the printed mission lacks its last ')': it is added on the last line.
; Units: cm and tenths of a degree. hilare_room: start (600 250) heading east, the east wall's
; face at x = 792.5 cm. The wall is perceived when a line lies 80 cm ahead (θ = 0: its normal
; points straight ahead); the goal is the line y = 700 cm (through (760 700), direction 0).
(define Tpath PATH1 ((740 250)))
(define Tnum ρ 80)
(define Tnum θ 0)
(define Tnum x 760)
(define Tnum y 700)
(define Tnum φ 0)

(MISSION mission1
(PRE: (eq motors ON))
(MAIN:
  (smooth-move(PATH1) MNTR(S_us-perception line (ρ, θ))
    => ((stop))((NEXT)))
  (RUN (wall-following (right-side 25))
    MNTR(S_straight-line (x, y, φ)) => ((stop))((NEXT)))
)
)
