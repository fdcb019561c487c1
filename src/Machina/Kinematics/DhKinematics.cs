namespace Machina;

/// <summary>
/// Kinematics of any six-joint serial arm given by a Denavit–Hartenberg table (<see cref="RobotModel.FromDh"/>). The forward chain is
/// exact; the inverse is numerical (damped least squares from several starting joint sets), accurate to 1e-9 mm, and lists the distinct
/// solutions it finds (up to eight). Joint values are the table's θ minus each row's offset, in degrees.
/// </summary>
public sealed class DhKinematics : IKinematics, ISolver
{
    private const int MaxIterations = 80;

    // A start that converges is within a micrometre after a dozen steps; one still a millimetre off after this many is abandoned.
    private const int GiveUpIteration = 30;
    private const double PositionTolerance = 1e-9, RotationTolerance = 1e-11;

    // Starting joint sets tried after the reference: every quarter turn of axis 1, both sides of axes 2 and 3, both signs of axis 5
    // (whole arm), the same for joints 1–3 alone (spherical wrist), and both signs of axis 5 with axis 4 at 0 or a half turn (wrist).
    private static readonly double[][] Seeds = BuildSeeds();
    private static readonly double[][] ArmSeeds = BuildArmSeeds();
    private static readonly double[][] WristSeeds = [[0, Math.PI / 3, 0], [0, -Math.PI / 3, 0], [Math.PI, Math.PI / 3, 0], [Math.PI, -Math.PI / 3, 0]];

    private readonly DhJoint[] _table;
    private readonly double[] _cosAlpha, _sinAlpha, _offset;
    private readonly Affine _flange;
    private readonly double _length;

    // Spherical wrist (axes 4, 5, 6 meet in one point): that point in the axis-4 frame, which only joints 1–3 move, and in the flange
    // frame. Null when the wrist is not spherical (then the inverse searches all six joints at once).
    private readonly Vector? _wristInAxis4;
    private readonly Vector _wristInFlange;

    // No point can be farther from the base origin than this (each link moves it by at most |a| + |d|): the wrist point, the flange.
    private readonly double _wristReach, _flangeReach;

    internal DhKinematics(RobotModel model, DhConvention convention, DhJoint[] table, Pose flange)
    {
        Model = model;
        Convention = convention;
        _table = table;
        _cosAlpha = table.Select(j => Math.Cos(j.Alpha * Angles.ToRadians)).ToArray();
        _sinAlpha = table.Select(j => Math.Sin(j.Alpha * Angles.ToRadians)).ToArray();
        _offset = table.Select(j => j.ThetaOffset * Angles.ToRadians).ToArray();
        _flange = Affine.FromPose(flange);
        // Orientation errors (radians) are weighed against position errors (mm) with the arm's size.
        _length = Math.Max(1, table.Sum(j => Math.Abs(j.A) + Math.Abs(j.D)) + flange.Position.Length);
        Span<double> zero = stackalloc double[6];
        Span<Affine> axes = stackalloc Affine[6];
        Affine end = Chain(zero, axes);
        Vector a4 = Z(axes[3]), a5 = Z(axes[4]), a6 = Z(axes[5]);
        Vector wrist = ClosestPoint(P(axes[3]), a4, P(axes[4]), a5);
        bool spherical = Vector.Cross(a4, a5).Length > 1e-6 && Vector.Cross(a5, a6).Length > 1e-6
            && DistanceToLine(wrist, P(axes[3]), a4) < 1e-7 && DistanceToLine(wrist, P(axes[4]), a5) < 1e-7 && DistanceToLine(wrist, P(axes[5]), a6) < 1e-7;
        if (spherical)
        {
            _wristInAxis4 = Transform(axes[3].InverseRigid(), wrist);
            _wristInFlange = Transform(end.InverseRigid(), wrist);
        }
        _flangeReach = _length + 1e-6;
        _wristReach = table.Take(4).Sum(j => Math.Abs(j.A) + Math.Abs(j.D)) + (_wristInAxis4?.Length ?? 0) + 1e-6;
    }

    private static Vector Z(in Affine f) => new(f.R02, f.R12, f.R22);

    private static Vector P(in Affine f) => new(f.Px, f.Py, f.Pz);

    private static Vector Transform(in Affine f, Vector v) => new(
        f.R00 * v.X + f.R01 * v.Y + f.R02 * v.Z + f.Px, f.R10 * v.X + f.R11 * v.Y + f.R12 * v.Z + f.Py, f.R20 * v.X + f.R21 * v.Y + f.R22 * v.Z + f.Pz);

    private static double DistanceToLine(Vector point, Vector onLine, Vector direction) => Vector.Cross(point - onLine, direction).Length;

    /// <inheritdoc/>
    public RobotModel Model { get; }

    /// <summary>Whether the table is standard or modified DH.</summary>
    public DhConvention Convention { get; }

    /// <summary>The six rows of the DH table (mm, degrees).</summary>
    public IReadOnlyList<DhJoint> Table => _table;

    /// <inheritdoc/>
    public Pose Forward(Joints joints)
    {
        joints.RequireFinite(nameof(joints));
        Span<double> q = stackalloc double[6];
        ToRadians(joints, q);
        Span<Affine> axes = stackalloc Affine[6];
        return Chain(q, axes).ToPose();
    }

    /// <summary>Where the arm's joints are for these joint values: the base, the origin of each joint's frame, the flange.</summary>
    internal Vector[] LinkPoints(Joints joints)
    {
        joints.RequireFinite(nameof(joints));
        Span<double> q = stackalloc double[6];
        ToRadians(joints, q);
        Span<Affine> axes = stackalloc Affine[6];
        Affine end = Chain(q, axes);
        var points = new Vector[8];
        points[0] = Vector.Zero;
        for (int i = 0; i < 6; i++)
        {
            points[i + 1] = P(axes[i]);
        }
        points[7] = P(end);
        return points;
    }

    private static void ToRadians(Joints joints, Span<double> q)
    {
        for (int i = 0; i < 6; i++)
        {
            q[i] = joints[i] * Angles.ToRadians;
        }
    }

    /// <summary>The flange for joint values in radians; <paramref name="axes"/> receives, per joint, a frame whose Z is that joint's axis.</summary>
    private Affine Chain(ReadOnlySpan<double> q, Span<Affine> axes)
    {
        Affine t = Affine.Identity;
        for (int i = 0; i < 6; i++)
        {
            double theta = q[i] + _offset[i];
            DhJoint row = _table[i];
            if (Convention == DhConvention.Standard)
            {
                axes[i] = t;
                t *= Affine.Dh(theta, row.D, row.A, _cosAlpha[i], _sinAlpha[i]);
            }
            else
            {
                t *= new Affine(1, 0, 0, 0, _cosAlpha[i], -_sinAlpha[i], 0, _sinAlpha[i], _cosAlpha[i], row.A, 0, 0);
                axes[i] = t;
                double c = Math.Cos(theta), s = Math.Sin(theta);
                t *= new Affine(c, -s, 0, s, c, 0, 0, 0, 1, 0, 0, row.D);
            }
        }
        return t * _flange;
    }

    /// <inheritdoc/>
    public int Inverse(Pose flange, Span<Joints> solutions) => KinematicsCore.Inverse(this, Model, flange, solutions);

    /// <inheritdoc/>
    public IReadOnlyList<Joints> Inverse(Pose flange) => KinematicsCore.InverseList(this, Model, flange);

    /// <inheritdoc/>
    public Joints? Closest(Pose flange, Joints current) => KinematicsCore.Closest(this, Model, flange, current);

    /// <inheritdoc/>
    public Joints? Solve(Pose flange, ArmConfiguration configuration) => KinematicsCore.Solve(this, Model, flange, configuration);

    /// <inheritdoc/>
    public bool IsWithinLimits(Joints joints) => KinematicsCore.IsWithinLimits(Model, joints);

    /// <inheritdoc/>
    public KinematicIssue? WhyNoSolution(Pose flange) => KinematicsCore.WhyNoSolution(this, Model, flange, Pose.Identity);

    /// <summary>
    /// The configuration, measured on the geometry (the same rules for every arm, so the flags stay consistent along a path): shoulder back
    /// when the wrist point is behind axis 1 (against axis 2 × axis 1), elbow down when the wrist point is on the far side of the line from
    /// axis 2 to axis 3, wrist flipped when axis 6 leans from axis 4 the opposite way to axis 5.
    /// </summary>
    public ArmConfiguration ConfigurationOf(Joints joints)
    {
        Geometry g = Measure(joints);
        return new ArmConfiguration(g.Forward < 0, g.ElbowSide < 0, g.WristSide < 0);
    }

    SingularityMeasure ISolver.Measure(Joints joints)
    {
        Geometry g = Measure(joints);
        return new SingularityMeasure(g.WristDegrees, g.ElbowDegrees, Math.Abs(g.Forward));
    }

    private readonly record struct Geometry(double Forward, double ElbowSide, double WristSide, double WristDegrees, double ElbowDegrees);

    private Geometry Measure(Joints joints)
    {
        joints.RequireFinite(nameof(joints));
        Span<double> q = stackalloc double[6];
        ToRadians(joints, q);
        Span<Affine> axes = stackalloc Affine[6];
        Chain(q, axes);
        Vector a1 = Z(axes[0]), a2 = Z(axes[1]), a3 = Z(axes[2]), a4 = Z(axes[3]), a5 = Z(axes[4]), a6 = Z(axes[5]);
        Vector p1 = P(axes[0]), p2 = P(axes[1]), p3 = P(axes[2]);
        Vector w = ClosestPoint(P(axes[3]), a4, P(axes[4]), a5);
        Vector forward = Vector.Cross(a2, a1);
        forward = forward.Length > 1e-9 ? forward * (1 / forward.Length) : new Vector(axes[0].R00, axes[0].R10, axes[0].R20);
        // Lower arm: from axis 2 to axis 3 across axis 3; forearm: from axis 3 to the wrist point, both seen along axis 3.
        Vector u = Across(p3 - p2, a3), v = Across(w - p3, a3);
        Vector wristCross = Vector.Cross(a4, a6), elbowCross = Vector.Cross(u, v);
        double uv = u.Length * v.Length;
        return new Geometry(
            Vector.Dot(w - p1, forward),
            Vector.Dot(elbowCross, a3),
            Vector.Dot(wristCross, a5),
            Math.Asin(Math.Min(1, wristCross.Length)) * Angles.ToDegrees,
            uv < 1e-9 ? 90 : Math.Asin(Math.Min(1, elbowCross.Length / uv)) * Angles.ToDegrees);

        static Vector Across(Vector d, Vector axis) => d - axis * Vector.Dot(d, axis);
    }

    /// <summary>The point midway between two lines where they come closest (the second line's point when they are parallel).</summary>
    private static Vector ClosestPoint(Vector p, Vector d, Vector r, Vector e)
    {
        Vector w0 = p - r;
        double b = Vector.Dot(d, e), den = 1 - b * b;
        if (den < 1e-12)
        {
            return r;
        }
        double s = (b * Vector.Dot(e, w0) - Vector.Dot(d, w0)) / den, t = (Vector.Dot(e, w0) - b * Vector.Dot(d, w0)) / den;
        return (p + d * s + r + e * t) * 0.5;
    }

    int ISolver.SolveRaw(in Affine flange, in Joints reference, Span<Joints> joints, Span<ArmConfiguration> configurations)
    {
        Span<double> q = stackalloc double[6], r = stackalloc double[6];
        ToRadians(reference, r);
        int count = 0;
        if (_wristInAxis4 is not null)
        {
            // Spherical wrist: the wrist point fixes joints 1–3 (up to four ways), then the rotation fixes 4–6 (two ways each).
            Vector wrist = Transform(flange, _wristInFlange);
            if (wrist.Length > _wristReach)
            {
                return 0;
            }
            Span<double> arms = stackalloc double[3 * 4];
            int armCount = 0;
            // A three-joint positioning chain reaches one point in at most four ways.
            for (int seed = -1; seed < ArmSeeds.Length && armCount < 4 && count < joints.Length; seed++)
            {
                ReadOnlySpan<double> start = seed < 0 ? r[..3] : ArmSeeds[seed];
                start.CopyTo(q);
                q[3] = q[4] = q[5] = 0;
                if (!ConvergeThree(false, flange, wrist, q) || IsListed(arms[..(3 * armCount)], q[..3]))
                {
                    continue;
                }
                q[..3].CopyTo(arms.Slice(3 * armCount++, 3));
                int before = count;
                // The wrist reaches one rotation in two ways: start from the reference's wrist (first arm only), then from fixed starts.
                for (int w = seed < 0 ? -1 : 0; w < WristSeeds.Length && count - before < 2 && count < joints.Length; w++)
                {
                    (w < 0 ? r[3..] : WristSeeds[w]).CopyTo(q[3..]);
                    arms.Slice(3 * (armCount - 1), 3).CopyTo(q);
                    if (ConvergeThree(true, flange, wrist, q) && Converge(flange, q))
                    {
                        count = Add(q, joints, configurations, count);
                    }
                }
            }
            return count;
        }
        if (new Vector(flange.Px, flange.Py, flange.Pz).Length > _flangeReach)
        {
            return 0;
        }
        for (int seed = -1; seed < Seeds.Length && count < joints.Length; seed++)
        {
            (seed < 0 ? r : Seeds[seed]).CopyTo(q);
            if (Converge(flange, q))
            {
                count = Add(q, joints, configurations, count);
            }
        }
        return count;
    }

    private int Add(ReadOnlySpan<double> q, Span<Joints> joints, Span<ArmConfiguration> configurations, int count)
    {
        var found = new Joints(
            KinematicsCore.WrapDegrees(q[0]), KinematicsCore.WrapDegrees(q[1]), KinematicsCore.WrapDegrees(q[2]),
            KinematicsCore.WrapDegrees(q[3]), KinematicsCore.WrapDegrees(q[4]), KinematicsCore.WrapDegrees(q[5]));
        foreach (Joints j in joints[..count])
        {
            if (SameAngles(j, found))
            {
                return count;
            }
        }
        configurations[count] = ConfigurationOf(found);
        joints[count] = found;
        return count + 1;
    }

    private static bool SameAngles(Joints a, Joints b)
    {
        for (int i = 0; i < 6; i++)
        {
            if (Math.Abs(Math.IEEERemainder(a[i] - b[i], 360)) >= 1e-5)
            {
                return false;
            }
        }
        return true;
    }

    /// <summary>True when the first three radians of <paramref name="q"/> match (modulo a turn) one of the triples in <paramref name="list"/>.</summary>
    private static bool IsListed(ReadOnlySpan<double> list, ReadOnlySpan<double> q)
    {
        for (int k = 0; k + 3 <= list.Length; k += 3)
        {
            bool same = true;
            for (int i = 0; i < 3 && same; i++)
            {
                same = Math.Abs(Math.IEEERemainder(list[k + i] - q[i], 2 * Math.PI)) < 1e-7;
            }
            if (same)
            {
                return true;
            }
        }
        return false;
    }

    /// <summary>
    /// Damped least squares on three joints (radians, in place), the others fixed: joints 1–3 to put the wrist point at
    /// <paramref name="wrist"/> (<paramref name="wristJoints"/> false), or joints 4–6 to give the flange <paramref name="target"/>'s rotation.
    /// </summary>
    private bool ConvergeThree(bool wristJoints, in Affine target, Vector wrist, Span<double> q)
    {
        Span<Affine> axes = stackalloc Affine[6];
        Span<double> e = stackalloc double[3], trialError = stackalloc double[3], j = stackalloc double[9], step = stackalloc double[3];
        Span<double> trial = stackalloc double[6];
        int first = wristJoints ? 3 : 0;
        double tolerance = wristJoints ? RotationTolerance * _length : PositionTolerance;
        double damping = 1e-3;
        double cost = ThreeError(wristJoints, target, wrist, q, axes, e);
        for (int iteration = 0; iteration < MaxIterations; iteration++)
        {
            if (Math.Abs(e[0]) + Math.Abs(e[1]) + Math.Abs(e[2]) < tolerance)
            {
                return true;
            }
            if (iteration == GiveUpIteration && cost > 1)
            {
                return false;   // still a millimetre away: this start leads nowhere (or the point is out of reach)
            }
            Vector point = wristJoints ? default : Transform(axes[3], _wristInAxis4!.Value);
            for (int i = 0; i < 3; i++)
            {
                Affine f = axes[first + i];
                // Moving the wrist point: axis × lever; turning the flange: the axis itself (scaled like the error).
                Vector c = wristJoints ? Z(f) * _length : Vector.Cross(Z(f), point - P(f));
                j[i] = c.X; j[3 + i] = c.Y; j[6 + i] = c.Z;
            }
            if (!Step(3, j, e, damping, step))
            {
                return false;
            }
            q.CopyTo(trial);
            for (int i = 0; i < 3; i++)
            {
                trial[first + i] += step[i];
            }
            double trialCost = ThreeError(wristJoints, target, wrist, trial, axes, trialError);
            if (trialCost < cost)
            {
                trial.CopyTo(q);
                trialError.CopyTo(e);
                bool stalled = cost - trialCost < 1e-9 * cost && trialCost > 1e-12;
                cost = trialCost;
                damping = Math.Max(damping * 0.1, 1e-15);
                if (stalled)
                {
                    break;   // stuck at a nearest point that is not the target (out of reach for this branch)
                }
            }
            else
            {
                ThreeError(wristJoints, target, wrist, q, axes, e);
                damping *= 10;
                if (damping > 1e6)
                {
                    break;
                }
            }
        }
        return Math.Abs(e[0]) + Math.Abs(e[1]) + Math.Abs(e[2]) < tolerance;
    }

    private double ThreeError(bool wristJoints, in Affine target, Vector wrist, ReadOnlySpan<double> q, Span<Affine> axes, Span<double> e)
    {
        Affine end = Chain(q, axes);
        if (wristJoints)
        {
            Span<double> full = stackalloc double[6];
            Error(target, end, full);
            full[3..].CopyTo(e);
        }
        else
        {
            Vector d = wrist - Transform(axes[3], _wristInAxis4!.Value);
            e[0] = d.X; e[1] = d.Y; e[2] = d.Z;
        }
        return e[0] * e[0] + e[1] * e[1] + e[2] * e[2];
    }

    /// <summary>Damped least squares (Levenberg–Marquardt) from <paramref name="q"/>; true when the flange is reached within tolerance.</summary>
    private bool Converge(in Affine target, Span<double> q)
    {
        Span<Affine> axes = stackalloc Affine[6];
        Span<double> error = stackalloc double[6], trialError = stackalloc double[6], trial = stackalloc double[6];
        Span<double> jacobian = stackalloc double[36], step = stackalloc double[6];
        Span<Affine> trialAxes = stackalloc Affine[6];
        Affine end = Chain(q, axes);
        double cost = Error(target, end, error);
        double damping = 1e-3;
        for (int iteration = 0; iteration < MaxIterations; iteration++)
        {
            if (IsConverged(error))
            {
                return true;
            }
            if (iteration == GiveUpIteration && cost > 1)
            {
                return false;
            }
            Jacobian(axes, end, jacobian);
            if (!Step(6, jacobian, error, damping, step))
            {
                return false;
            }
            for (int i = 0; i < 6; i++)
            {
                trial[i] = q[i] + step[i];
            }
            Affine trialEnd = Chain(trial, trialAxes);
            double trialCost = Error(target, trialEnd, trialError);
            if (trialCost < cost)
            {
                trial.CopyTo(q);
                trialAxes.CopyTo(axes);
                trialError.CopyTo(error);
                end = trialEnd;
                bool stalled = cost - trialCost < 1e-9 * cost && trialCost > 1e-12;
                cost = trialCost;
                damping = Math.Max(damping * 0.1, 1e-15);
                if (stalled)
                {
                    break;   // stuck at a nearest pose that is not the target
                }
            }
            else
            {
                damping *= 10;
                if (damping > 1e6)
                {
                    return IsConverged(error);
                }
            }
        }
        return IsConverged(error);
    }

    private bool IsConverged(ReadOnlySpan<double> error) =>
        Math.Abs(error[0]) + Math.Abs(error[1]) + Math.Abs(error[2]) < PositionTolerance
        && (Math.Abs(error[3]) + Math.Abs(error[4]) + Math.Abs(error[5])) / _length < RotationTolerance;

    /// <summary>Position error (mm) and rotation error (radians, exact rotation vector, scaled by the arm's size); returns the squared norm.</summary>
    private double Error(in Affine target, in Affine current, Span<double> error)
    {
        error[0] = target.Px - current.Px;
        error[1] = target.Py - current.Py;
        error[2] = target.Pz - current.Pz;
        // R = target · currentᵀ, the rotation still to make, in the base frame.
        Affine r = target * current.InverseRigid();
        double x = r.R21 - r.R12, y = r.R02 - r.R20, z = r.R10 - r.R01;
        double sin2 = Math.Sqrt(x * x + y * y + z * z), cos = (r.R00 + r.R11 + r.R22 - 1) / 2;
        double angle = Math.Atan2(sin2 / 2, cos);
        double scale;
        if (sin2 > 1e-9)
        {
            scale = angle / sin2;
        }
        else if (cos > 0)
        {
            scale = 0.5;
        }
        else
        {
            // Half a turn: the axis is the column of (R + I) / 2 with the largest diagonal.
            int k = r.R00 >= r.R11 && r.R00 >= r.R22 ? 0 : r.R11 >= r.R22 ? 1 : 2;
            (x, y, z) = k switch
            {
                0 => (r.R00 + 1, r.R10, r.R20),
                1 => (r.R01, r.R11 + 1, r.R21),
                _ => (r.R02, r.R12, r.R22 + 1),
            };
            scale = Math.PI / Math.Sqrt(x * x + y * y + z * z);
        }
        error[3] = x * scale * _length;
        error[4] = y * scale * _length;
        error[5] = z * scale * _length;
        double sum = 0;
        foreach (double e in error)
        {
            sum += e * e;
        }
        return sum;
    }

    /// <summary>Row-major 6×6 Jacobian: rows x, y, z (mm/rad) and the rotation rows (scaled by the arm's size).</summary>
    private void Jacobian(ReadOnlySpan<Affine> axes, in Affine end, Span<double> jacobian)
    {
        for (int i = 0; i < 6; i++)
        {
            Affine f = axes[i];
            double zx = f.R02, zy = f.R12, zz = f.R22;
            double dx = end.Px - f.Px, dy = end.Py - f.Py, dz = end.Pz - f.Pz;
            jacobian[0 * 6 + i] = zy * dz - zz * dy;
            jacobian[1 * 6 + i] = zz * dx - zx * dz;
            jacobian[2 * 6 + i] = zx * dy - zy * dx;
            jacobian[3 * 6 + i] = zx * _length;
            jacobian[4 * 6 + i] = zy * _length;
            jacobian[5 * 6 + i] = zz * _length;
        }
    }

    /// <summary>step = Jᵀ (J Jᵀ + λ·mean(diag)·I)⁻¹ e for a row-major n×n Jacobian (n = 3 or 6); false when it cannot be solved.</summary>
    private static bool Step(int n, ReadOnlySpan<double> j, ReadOnlySpan<double> e, double damping, Span<double> step)
    {
        int w = n + 1;
        Span<double> m = stackalloc double[42];
        double trace = 0;
        for (int r = 0; r < n; r++)
        {
            for (int c = 0; c < n; c++)
            {
                double s = 0;
                for (int k = 0; k < n; k++)
                {
                    s += j[r * n + k] * j[c * n + k];
                }
                m[r * w + c] = s;
            }
            trace += m[r * w + r];
            m[r * w + n] = e[r];
        }
        double lambda = damping * Math.Max(trace / n, 1e-12);
        for (int r = 0; r < n; r++)
        {
            m[r * w + r] += lambda;
        }
        // Gaussian elimination with partial pivoting on the augmented n×(n+1) matrix.
        for (int col = 0; col < n; col++)
        {
            int pivot = col;
            for (int r = col + 1; r < n; r++)
            {
                if (Math.Abs(m[r * w + col]) > Math.Abs(m[pivot * w + col]))
                {
                    pivot = r;
                }
            }
            if (!(Math.Abs(m[pivot * w + col]) > 1e-300))
            {
                return false;
            }
            if (pivot != col)
            {
                for (int c = 0; c < w; c++)
                {
                    (m[col * w + c], m[pivot * w + c]) = (m[pivot * w + c], m[col * w + c]);
                }
            }
            for (int r = col + 1; r < n; r++)
            {
                double f = m[r * w + col] / m[col * w + col];
                for (int c = col; c < w; c++)
                {
                    m[r * w + c] -= f * m[col * w + c];
                }
            }
        }
        Span<double> y = stackalloc double[6];
        for (int r = n - 1; r >= 0; r--)
        {
            double s = m[r * w + n];
            for (int c = r + 1; c < n; c++)
            {
                s -= m[r * w + c] * y[c];
            }
            y[r] = s / m[r * w + r];
        }
        bool finite = true;
        for (int i = 0; i < n; i++)
        {
            double s = 0;
            for (int r = 0; r < n; r++)
            {
                s += j[r * n + i] * y[r];
            }
            step[i] = s;
            finite &= double.IsFinite(s);
        }
        return finite;
    }

    private static double[][] BuildArmSeeds()
    {
        var seeds = new List<double[]>();
        foreach (double j3 in (ReadOnlySpan<double>)[-90, 90, 0])
        {
            foreach (double j1 in (ReadOnlySpan<double>)[0, 180, 90, -90])
            {
                foreach (double j2 in (ReadOnlySpan<double>)[-45, 45, -135, 135])
                {
                    seeds.Add([j1 * Angles.ToRadians, j2 * Angles.ToRadians, j3 * Angles.ToRadians]);
                }
            }
        }
        return [.. seeds];
    }

    private static double[][] BuildSeeds()
    {
        var seeds = new List<double[]>();
        foreach (double j1 in (ReadOnlySpan<double>)[0, 180, 90, -90])
        {
            foreach (double j3 in (ReadOnlySpan<double>)[-90, 90])
            {
                foreach (double j2 in (ReadOnlySpan<double>)[-45, 45])
                {
                    foreach (double j5 in (ReadOnlySpan<double>)[60, -60])
                    {
                        seeds.Add([j1 * Angles.ToRadians, j2 * Angles.ToRadians, j3 * Angles.ToRadians, 0, j5 * Angles.ToRadians, 0]);
                    }
                }
            }
        }
        return [.. seeds];
    }
}
