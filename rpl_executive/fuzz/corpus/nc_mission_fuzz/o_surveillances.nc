; O-surveillances of HILARE (section 4.1.1): monitors of the robot's operation, always on,
; whether a mission runs or not. A low battery stops the robot and fails the running mission.
(OSURV:
  MNTR (S_battery-level BELOW 15) => ((stop)) ((FAIL)))
