; Program "JointsToolsIO" written by Machina 0.1.0 for ZMORPH.
; Safety: this program moves a machine that can hurt people. Check it in simulation first,
; run it at reduced speed, keep clear of the working area and keep the emergency stop in reach.

G90
M82
G92 E0

; ACTION "Set joint rotations to [0, 0, 0, 0, 90, 0] deg" NOT APPLICABLE TO THIS DEVICE  ; [Set joint rotations to [0, 0, 0, 0, 90, 0] deg]
; ACTION "Set motion type to 'Joint'" NOT APPLICABLE TO THIS DEVICE  ; [Set motion type to 'Joint']
G1 F1200
G1 X400 Y0 Z400  ; [Transform: move to [400, 0, 400] mm and rotate to [[-1, 0, 0], [0, 1, 0], [0, 0, -1]]]
; [Define tool "pen" on the Robot.]
; ACTION "Attach tool "pen" to robot flange." NOT APPLICABLE TO THIS DEVICE  ; [Attach tool "pen" to robot flange.]
; [Set motion type to 'Linear']
G1 X400 Y0 Z250  ; [Move [0, 0, -50] mm]
M42 P1 S1  ; [Turn digital IO 1 ON]
; WARNING: printer outputs take whole values from 0 to 255; 0.5 is rounded to 1.
M42 P2 S1  ; [Set analog IO 2 to 0.5]
G4 P500  ; [Wait 500 ms]
; ERROR on "Turn tool digital IO "DO_Gripper" OFF": a 3D printer has no separate tool outputs.  ; [Turn tool digital IO "DO_Gripper" OFF]
; ACTION "Detach all tools from robot." NOT APPLICABLE TO THIS DEVICE  ; [Detach all tools from robot.]
; ACTION "Set joint rotations to [0, -30, 30, 0, 60, 0] deg" NOT APPLICABLE TO THIS DEVICE  ; [Set joint rotations to [0, -30, 30, 0, 60, 0] deg]
; ACTION "Increase joint rotations by [10, 0, 0, 0, 0, 0] deg" NOT APPLICABLE TO THIS DEVICE  ; [Increase joint rotations by [10, 0, 0, 0, 0, 0] deg]
