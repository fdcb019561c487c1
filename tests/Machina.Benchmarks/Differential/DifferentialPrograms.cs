using System.Globalization;

namespace Machina.Benchmarks.Differential;

/// <summary>
/// Seeded random programs (Machina instruction text) over every verb a brand's driver takes: motions of every kind (linear,
/// joint, absolute and relative, world and local, rotations, joint targets), arcs (through points only, with planes, relative),
/// tools, speeds, accelerations, zones, outputs, waits (timed, and for inputs), input reads, messages and settings stacks. The targets stay in a box every brand's
/// arm reaches with the tool pointing down (or tilted up to 20°), so most programs run to their end; some do not, and both runs
/// must then stop at the same action. The same seed gives the same program.
/// </summary>
internal static class DifferentialPrograms
{
    private static readonly Vector Low = new(300, -80, 400);
    private static readonly Vector High = new(420, 80, 520);

    /// <summary>The program of <paramref name="seed"/> for <paramref name="brand"/>, one instruction per line.</summary>
    internal static string Random(RobotType brand, int seed)
    {
        var g = new Generator(brand, Model(brand), new Random(seed));
        return g.Program();
    }

    /// <summary>The brands of the differential property: those with a driver and a twin.</summary>
    internal static readonly RobotType[] Brands = [RobotType.ABB, RobotType.UR, RobotType.KUKA];

    /// <summary>The arm <c>machina verify</c> and the virtual controller take for <paramref name="brand"/> by default.</summary>
    internal static RobotModel Model(RobotType brand) => RobotModels.Get(brand switch
    {
        RobotType.UR => "UR5e",
        RobotType.KUKA => "KR 6 R900 sixx",
        _ => "IRB 120",
    });

    private sealed class Generator(RobotType brand, RobotModel model, Random random)
    {
        private readonly List<string> _lines = [];
        private Vector _at;
        private Rotation _rot = Rotation.FlippedAroundY;
        private Joints? _joints;
        private double _tool; // length of the attached tool along its z axis, 0 for none
        private bool _local;
        private int _pushed;
        private int _tools;
        private readonly List<(string Name, double Length)> _defined = [];
        // Verb families some programs leave out, so that a brand whose driver refuses one (UR: Coordinates; UR and KUKA: arcs,
        // until their drivers take them) still streams the rest of its programs.
        private readonly bool _arcs = random.Next(2) == 0;
        private readonly bool _frames = random.Next(3) == 0;

        internal string Program()
        {
            Emit($"SpeedTo({random.Next(20, 250)})");
            Emit(random.Next(2) == 0 ? "MotionMode(\"joint\")" : "MotionMode(\"linear\")");
            _at = Point();
            if (random.Next(4) == 0)
            {
                AxesToPose();
            }
            else
            {
                Emit($"TransformTo({P(_at)}, {Axes(_rot)})");
            }
            int steps = random.Next(6, 22);
            for (int i = 0; i < steps; i++)
            {
                Step();
            }
            return string.Join('\n', _lines) + "\n";
        }

        private void Step()
        {
            switch (random.Next(30))
            {
                case 0 or 1 or 2:
                    MoveBy(new Vector(random.Next(-40, 41), random.Next(-40, 41), random.Next(-40, 41)));
                    break;
                case 3 or 4:
                    _at = Point();
                    _joints = null;
                    Emit($"MoveTo({P(_at)})");
                    break;
                case 5 or 6:
                    _at = Point();
                    _rot = Tilted();
                    _joints = null;
                    Emit($"TransformTo({P(_at)}, {Axes(_rot)})");
                    break;
                case 7:
                    _rot = Tilted();
                    _joints = null;
                    Emit($"RotateTo({Axes(_rot)})");
                    break;
                case 8:
                    RotateBy();
                    break;
                case 9 or 10 when _arcs:
                    Arc(positionOnly: true);
                    break;
                case 11 when _arcs:
                    Arc(positionOnly: false);
                    break;
                case 12 when _arcs:
                    RelativeArc();
                    break;
                case 13:
                    AxesToPose();
                    break;
                case 14:
                    if (_joints is Joints q)
                    {
                        var by = new Joints(Inc(), Inc(), Inc(), Inc(), Inc(), Inc());
                        Emit($"Axes({J(by)})");
                        Track(new Joints(q.J1 + by.J1, q.J2 + by.J2, q.J3 + by.J3, q.J4 + by.J4, q.J5 + by.J5, q.J6 + by.J6));
                    }
                    break;
                case 15:
                    Emit(random.Next(3) == 0 ? $"Speed({random.Next(-10, 30)})" : $"SpeedTo({random.Next(10, 300)})");
                    break;
                case 16:
                    Emit(random.Next(3) == 0 ? $"Acceleration({random.Next(0, 200)})" : $"AccelerationTo({random.Next(100, 3000)})");
                    break;
                case 17:
                    Emit(random.Next(3) == 0 ? $"Precision({random.Next(0, 3)})" : $"PrecisionTo({random.Next(0, 11)})");
                    break;
                case 18:
                    Emit($"Wait({random.Next(0, 300)})");
                    break;
                case 19:
                    Emit($"Message(\"step {_lines.Count}\")");
                    break;
                case 20:
                    _pushed++;
                    Emit("PushSettings()");
                    break;
                case 21:
                    if (_pushed > 0)
                    {
                        _pushed--;
                        Emit("PopSettings()");
                    }
                    break;
                case 22 or 23:
                    Tool();
                    break;
                case 24 or 25:
                    Output();
                    break;
                case 26 when _frames:
                    _local = !_local;
                    Emit(_local ? "Coordinates(\"local\")" : "Coordinates(\"world\")");
                    break;
                case 27:
                    Emit(random.Next(2) == 0 ? "MotionMode(\"joint\")" : "MotionMode(\"linear\")");
                    break;
                case 28:
                    Input();
                    break;
                default:
                    MoveBy(new Vector(random.Next(-15, 16), random.Next(-15, 16), random.Next(-15, 16)));
                    break;
            }
        }

        private void Emit(string line) => _lines.Add(line + ";");

        private double Inc() => random.Next(-50, 51) / 10.0;

        private Vector Point() => new(random.Next((int)Low.X, (int)High.X + 1), random.Next((int)Low.Y, (int)High.Y + 1), random.Next((int)Low.Z, (int)High.Z + 1));

        private static Vector Clamp(Vector v) => new(Math.Clamp(v.X, Low.X, High.X), Math.Clamp(v.Y, Low.Y, High.Y), Math.Clamp(v.Z, Low.Z, High.Z));

        /// <summary>The tool pointing down, tilted up to 20° about a horizontal axis.</summary>
        private Rotation Tilted()
        {
            double heading = random.Next(0, 360) * Math.PI / 180;
            return Rotation.FromAxisAngle(new Vector(Math.Cos(heading), Math.Sin(heading), 0), random.Next(0, 21)) * Rotation.FlippedAroundY;
        }

        private void MoveBy(Vector world)
        {
            Vector target = Clamp(_at + world);
            world = target - _at;
            Vector given = _local ? _rot.Inverse() * world : world;
            given = new Vector(Math.Round(given.X, 2), Math.Round(given.Y, 2), Math.Round(given.Z, 2));
            _at += _local ? _rot * given : given;
            _joints = null;
            Emit($"Move({P(given)})");
        }

        private void RotateBy()
        {
            Vector axis = new(random.Next(-10, 11), random.Next(-10, 11), random.Next(1, 11));
            int degrees = random.Next(-10, 11);
            Rotation by = Rotation.FromAxisAngle(axis, degrees);
            Rotation next = _local ? _rot * by : by * _rot;
            if (TwinTilt(next) > 25)
            {
                return;
            }
            _rot = next;
            _joints = null;
            Emit($"Rotate({P(axis)}, {degrees})");
        }

        private static double TwinTilt(Rotation r)
        {
            Vector z = r * new Vector(0, 0, 1);
            return Math.Acos(Math.Clamp(-z.Z, -1, 1)) * 180 / Math.PI;
        }

        private void Arc(bool positionOnly)
        {
            Vector end = Point();
            Vector chord = end - _at;
            if (chord.Length < 20)
            {
                return;
            }
            Vector side = Vector.CrossProduct(chord, new Vector(random.Next(-5, 6), random.Next(-5, 6), 10));
            if (side.Length < 1e-6)
            {
                return;
            }
            Vector mid = (_at + end) * 0.5;
            Vector through = Clamp(mid + side * (random.Next(5, 40) / side.Length));
            through = new Vector(Math.Round(through.X), Math.Round(through.Y), Math.Round(through.Z));
            if (Vector.Distance(through, mid) < 3)
            {
                return;
            }
            _joints = null;
            if (positionOnly)
            {
                Emit($"ArcMotionTo({P(through)}, {P(end)})");
            }
            else
            {
                Rotation via = Tilted(), to = Tilted();
                Emit($"ArcMotionTo({P(through)}, {Axes(via)}, {P(end)}, {Axes(to)})");
                _rot = to;
            }
            _at = end;
        }

        private void RelativeArc()
        {
            var by = new Vector(random.Next(-40, 41), random.Next(-40, 41), 0);
            var through = new Vector(by.X / 2 + random.Next(5, 20), by.Y / 2 - random.Next(5, 20), random.Next(-10, 11));
            if (by.Length < 20 || Clamp(_at + by) != _at + by || Clamp(_at + through) != _at + through || _local)
            {
                return;
            }
            _joints = null;
            _at += by;
            Emit($"ArcMotion({P(through)}, {P(by)})");
        }

        /// <summary>A joint target: the arm's solution for a point of the box, tool down or tilted, in degrees with 2 decimals.</summary>
        private void AxesToPose()
        {
            Vector at = Point();
            Rotation rot = random.Next(2) == 0 ? Rotation.FlippedAroundY : Tilted();
            Pose flange = new Pose(at, rot) * new Pose(new Vector(0, 0, _tool), Rotation.Identity).Inverse();
            if (model.Kinematics.Closest(flange, Start(brand)) is not Joints q)
            {
                return;
            }
            q = new Joints(Math.Round(q.J1, 2), Math.Round(q.J2, 2), Math.Round(q.J3, 2), Math.Round(q.J4, 2), Math.Round(q.J5, 2), Math.Round(q.J6, 2));
            Emit($"AxesTo({J(q)})");
            Track(q);
        }

        private void Track(Joints q)
        {
            Pose tcp = model.Kinematics.Forward(q) * new Pose(new Vector(0, 0, _tool), Rotation.Identity);
            (_at, _rot, _joints) = (tcp.Position, tcp.Rotation, q);
        }

        private void Tool()
        {
            if (_tool > 0 && random.Next(2) == 0)
            {
                _at -= _rot * new Vector(0, 0, _tool);
                _tool = 0;
                Emit("DetachTool()");
                return;
            }
            if (_defined.Count == 0 || random.Next(3) == 0)
            {
                string name = $"tool{++_tools}";
                double length = random.Next(0, 41);
                double kg = random.Next(1, 30) / 10.0;
                _defined.Add((name, length));
                Emit($"DefineTool(\"{name}\", 0, 0, {N(length)}, 1, 0, 0, 0, 1, 0, {N(kg)}, 0, 0, {N(length / 2)})");
            }
            (string tool, double toolLength) = _defined[random.Next(_defined.Count)];
            _at += _rot * new Vector(0, 0, toolLength - _tool);
            _tool = toolLength;
            Emit($"AttachTool(\"{tool}\")");
        }

        /// <summary>An output the brand's driver takes: named ABB signals (DO_n, AO_n), UR's standard and tool outputs, KUKA's $OUT and $ANOUT.</summary>
        private void Output()
        {
            bool on = random.Next(2) == 0;
            bool analog = random.Next(3) == 0;
            string line = brand switch
            {
                RobotType.ABB => analog ? $"WriteAnalog(\"AO_{random.Next(1, 5)}\", {N(random.Next(0, 1001) / 100.0)})" : $"WriteDigital(\"DO_{random.Next(1, 17)}\", {B(on)})",
                RobotType.UR => analog ? $"WriteAnalog({random.Next(0, 2)}, {N(random.Next(0, 101) / 100.0)})"
                    : random.Next(4) == 0 ? $"WriteDigital({random.Next(0, 2)}, {B(on)}, true)" : $"WriteDigital({random.Next(0, 8)}, {B(on)})",
                _ => analog ? $"WriteAnalog({random.Next(1, 5)}, {N(random.Next(-100, 101) / 100.0)})" : $"WriteDigital({random.Next(1, 17)}, {B(on)})",
            };
            Emit(line);
        }

        /// <summary>A wait for an input the twins hold at 0 (so it passes at once), with or without a time limit, or a read of one.</summary>
        private void Input()
        {
            string pin = brand switch
            {
                RobotType.ABB => $"\"DI_{random.Next(1, 17)}\"",
                RobotType.UR => $"{random.Next(0, 8)}",
                _ => $"{random.Next(1, 17)}",
            };
            Emit(random.Next(3) switch
            {
                0 => $"WaitForDigital({pin}, false)",
                1 => $"WaitForDigital({pin}, false, {random.Next(100, 1000)})",
                _ => $"ReadDigital({pin})",
            });
        }

        private static string B(bool on) => on ? "true" : "false";

        private static string N(double v) => v.ToString("0.###", CultureInfo.InvariantCulture);

        private static string P(Vector v) => $"{N(v.X)}, {N(v.Y)}, {N(v.Z)}";

        private static string J(Joints q) => $"{N(q.J1)}, {N(q.J2)}, {N(q.J3)}, {N(q.J4)}, {N(q.J5)}, {N(q.J6)}";

        private static string Axes(Rotation r)
        {
            Vector x = r.XAxis, y = r.YAxis;
            static string R(double v) => Math.Round(v, 6).ToString("0.######", CultureInfo.InvariantCulture);
            return $"{R(x.X)}, {R(x.Y)}, {R(x.Z)}, {R(y.X)}, {R(y.Y)}, {R(y.Z)}";
        }
    }

    /// <summary>Where each brand's virtual controller starts, near which joint targets are solved.</summary>
    internal static Joints Start(RobotType brand) => brand switch
    {
        RobotType.UR => new Joints(0, -90, -90, -90, 90, 0),
        RobotType.KUKA => new Joints(0, -90, 90, 0, 90, 0),
        _ => new Joints(0, 0, 0, 0, 90, 0),
    };
}
