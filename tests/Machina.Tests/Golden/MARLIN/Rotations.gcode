; Program "Rotations" written by Machina 0.1.0 for MARLIN.
; Safety: this program moves a machine that can hurt people. Check it in simulation first,
; run it at reduced speed, keep clear of the working area and keep the emergency stop in reach.

G21
G90
M82
G92 E0

G0 X300 Y200 Z400 F1200  ; [Move to [300, 200, 400] mm]
; ACTION "Rotate 45 deg around [0, 0, 1]" NOT APPLICABLE TO THIS DEVICE  ; [Rotate 45 deg around [0, 0, 1]]
; [Set reference coordinate system to 'Local']
; ACTION "Rotate 30 deg around [1, 0, 0]" NOT APPLICABLE TO THIS DEVICE  ; [Rotate 30 deg around [1, 0, 0]]
G0 X307.071 Y192.929 Z382.679  ; [Move [0, 0, 20] mm]
; [Set reference coordinate system to 'World']
; ACTION "Rotate to [[0, 1, 0], [1, 0, 0], [0, 0, -1]]" NOT APPLICABLE TO THIS DEVICE  ; [Rotate to [[0, 1, 0], [1, 0, 0], [0, 0, -1]]]
; WARNING: a 3D printer cannot turn its tool; the change of orientation is ignored.
G0 X350 Y250 Z450  ; [Transform: move to [350, 250, 450] mm and rotate to [[-1, 0, 0], [0, 1, 0], [0, 0, -1]]]
; ACTION "Rotate 20 deg around [0, 1, 0]" NOT APPLICABLE TO THIS DEVICE  ; [Rotate 20 deg around [0, 1, 0]]
