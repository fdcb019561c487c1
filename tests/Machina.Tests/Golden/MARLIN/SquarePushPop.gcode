; Program "SquarePushPop" written by Machina 0.1.0 for MARLIN.
; Safety: this program moves a machine that can hurt people. Check it in simulation first,
; run it at reduced speed, keep clear of the working area and keep the emergency stop in reach.

G21
G90
M82
G92 E0

; [Set motion speed to 50 mm/s or deg/s]
M204 P500 T500  ; [Set motion acceleration to 500 mm/s^2 or deg/s^2]
G0 X300 Y0 Z300 F3000  ; [Move to [300, 0, 300] mm]
; [Push settings to buffer]
; [Set motion speed to 200 mm/s or deg/s]
; ACTION "Set precision radius to 10 mm" NOT APPLICABLE TO THIS DEVICE  ; [Set precision radius to 10 mm]
M204 P1000 T1000  ; [Set motion acceleration to 1000 mm/s^2 or deg/s^2]
G0 X350 Y0 Z300 F12000  ; [Move [50, 0, 0] mm]
G0 X350 Y50 Z300  ; [Move [0, 50, 0] mm]
G0 X300 Y50 Z300  ; [Move [-50, 0, 0] mm]
G0 X300 Y0 Z300  ; [Move [0, -50, 0] mm]
M204 P500 T500  ; [Pop settings]
G0 X300 Y0 Z350 F3000  ; [Move [0, 0, 50] mm]
