; Program "SquarePushPop" written by Machina 0.1.0 for ZMORPH.
; Safety: this program moves a machine that can hurt people. Check it in simulation first,
; run it at reduced speed, keep clear of the working area and keep the emergency stop in reach.

G90
M82
G92 E0

G1 F3000  ; [Set motion speed to 50 mm/s or deg/s]
; ACTION "Set motion acceleration to 500 mm/s^2 or deg/s^2" NOT APPLICABLE TO THIS DEVICE  ; [Set motion acceleration to 500 mm/s^2 or deg/s^2]
G1 X300 Y0 Z300  ; [Move to [300, 0, 300] mm]
; [Push settings to buffer]
G1 F12000  ; [Set motion speed to 200 mm/s or deg/s]
; ACTION "Set precision radius to 10 mm" NOT APPLICABLE TO THIS DEVICE  ; [Set precision radius to 10 mm]
; ACTION "Set motion acceleration to 1000 mm/s^2 or deg/s^2" NOT APPLICABLE TO THIS DEVICE  ; [Set motion acceleration to 1000 mm/s^2 or deg/s^2]
G1 X350 Y0 Z300  ; [Move [50, 0, 0] mm]
G1 X350 Y50 Z300  ; [Move [0, 50, 0] mm]
G1 X300 Y50 Z300  ; [Move [-50, 0, 0] mm]
G1 X300 Y0 Z300  ; [Move [0, -50, 0] mm]
G1 F3000  ; [Pop settings]
G1 X300 Y0 Z350  ; [Move [0, 0, 50] mm]
