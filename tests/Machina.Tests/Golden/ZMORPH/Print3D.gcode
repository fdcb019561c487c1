; Program "Print3D" written by Machina 0.1.0 for ZMORPH.
; Safety: this program moves a machine that can hurt people. Check it in simulation first,
; run it at reduced speed, keep clear of the working area and keep the emergency stop in reach.

G90
M82
G92 E0

G91
G1 Z1.000 F200.000
G90
G28 X0.000 Y0.00
G1 X117.500 Y125.000 F8000.000
G28 Z0.000
G92 E0.00000
M82
G1 F1200
; [Initialize this device.]
M140 S60  ; [Set Bed temperature to 60 C]
M109 S210  ; [Set Extruder temperature to 210 C and wait]
M190 S60  ; [Set Bed temperature to 60 C and wait]
G1 F1800  ; [Set motion speed to 30 mm/s or deg/s]
G1 X50 Y50 Z0.3  ; [Move to [50, 50, 0.3] mm]
; [Set extrusion rate to 0.05 mm/mm]
; [Turn extrusion on]
G1 X70 Y50 Z0.3 E1  ; [Move [20, 0, 0] mm]
G1 X70 Y70 Z0.3 E2  ; [Move [0, 20, 0] mm]
G1 X50 Y70 Z0.3 E3  ; [Move [-20, 0, 0] mm]
G1 X50 Y50 Z0.3 E4  ; [Move [0, -20, 0] mm]
G1 X50 Y50 Z0.5 E4.01  ; [Move [0, 0, 0.2] mm]
G1 X70 Y50 Z0.5 E5.01  ; [Move [20, 0, 0] mm]
G1 X70 Y70 Z0.5 E6.01  ; [Move [0, 20, 0] mm]
G1 X50 Y70 Z0.5 E7.01  ; [Move [-20, 0, 0] mm]
G1 X50 Y50 Z0.5 E8.01  ; [Move [0, -20, 0] mm]
G1 X50 Y50 Z0.7 E8.02  ; [Move [0, 0, 0.2] mm]
; [Turn extrusion off]
G1 X50 Y50 Z10.7  ; [Move [0, 0, 10] mm]
G92 E0.0000
G91
G1 E-3.00000 F1800.000
G90
G92 E0.00000
G1 Z30.581 F300
G1 X117.5 Y220
T0
M104 S0
T1
M104 S0
M140 S0
M106 S0
M84
M220 S100
; [Terminate this device.]
