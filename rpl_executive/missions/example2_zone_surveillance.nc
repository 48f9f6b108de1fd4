; Noreils and Chatila, section 6.2.2, Example 2: reporting the sonar readings inside ZONE109;
; an unexpected obstacle on the path inside the zone makes the mission FAIL. As printed, with
; these typographic normalizations (README "The paper's missions as files"):
;   - the paper's elision line "..." after the definitions is this comment's last line;
;   - the printed mission lacks its last ')': it is added on the last line.
; Units: cm, tenths of a degree (PATH's 2700 is a final heading of 270.0 degrees), cm/s.
(define Tclist[4] ZONE109 ((150 500)(150 700)(350 700)(350 500)))
(define Tclist[4] sensors-list ((1 40)(2 50)(3 50)(4 40)))
(define Tpath PATH ((180 520)(350 520)(360 320 2700)))
; ...
(MISSION mission2
(PRE: (eq motor ON)(not (eq robot-in-zone $ZONE109)))
(ENV: (set LOA T))
(MAIN:
  (smooth-move(PATH)
    MNTR(S_zone IN ZONE109) => ((set-speed 20)){
      (set robot-in-zone ZONE109)
      (set LOA NIL)
      (MNTR(S_zone OUT ZONE109) => ((set-speed 50)){
        (set robot-in-zone NIL)
        (set LOA T)
      })
      (WHILE (robot-in-zone)
        (read-all-us-data)
        (draw %G_pos%G_echoes r-position r-us-data)
      )
    }
    MNTR STATIC (S_us-threshold sensors-list) => ((stop)) {
      (IF (LOA)
        ((avoid-obstacle)(resume-order))
        ((FAIL))
      )
    }
  )
)
)
