; Program "HelloRobot" written by Machina 0.1.0 for ZMORPH.
; Safety: this program moves a machine that can hurt people. Check it in simulation first,
; run it at reduced speed, keep clear of the working area and keep the emergency stop in reach.

G90
M82
G92 E0

M70 P1000 (Hello Robot!)  ; [Display message "Hello Robot!"]
G1 F6000  ; [Set motion speed to 100 mm/s or deg/s]
G1 X400 Y300 Z500  ; [Move to [400, 300, 500] mm]
; ACTION "Rotate -90 deg around [0, 1, 0]" NOT APPLICABLE TO THIS DEVICE  ; [Rotate -90 deg around [0, 1, 0]]
G1 X400 Y300 Z750  ; [Move [0, 0, 250] mm]
G4 P2000  ; [Wait 2000 ms]
; ACTION "Set joint rotations to [0, 0, 0, 0, 90, 0] deg" NOT APPLICABLE TO THIS DEVICE  ; [Set joint rotations to [0, 0, 0, 0, 90, 0] deg]
