namespace Machina.Simulation.Krl;

/// <summary>
/// The system routines KRL programs call (BAS is in <see cref="KrlBasicPackage"/>): IR_STOPM (its stop-message interrupt),
/// INVERSE, StrCopy, StrAdd, StrLen, Set_KrlMsg, MsgNotify and MsgNotifyTextPar, the mathematical functions, and EthernetKRL's EKI_GetFrameArray (the other EKI_ routines are the
/// controller's, see KrlTwinController.Eki.cs).
/// </summary>
internal static class KrlBuiltins
{
    /// <summary>Adds the system routines (EthernetKRL has its own).</summary>
    public static void AddTo(KrlEnvironment environment)
    {
        void Add(KrlBuiltin builtin) => environment.Builtins[builtin.Name] = builtin;
        Add(new("IR_STOPM", null, [], (_, _) => null));
        Add(new("INVERSE", KrlTypes.E6Axis, [new(KrlTypes.E6Pos), new(KrlTypes.E6Axis), new(KrlType.Int, IsOut: true)], Inverse)
        {
            WritesOnlyArguments = true, ReturnsFresh = true,
        });
        Add(new("StrCopy", KrlType.Bool, [new(KrlType.Array(KrlType.Char, 0), IsOut: true), KrlBuiltinParameter.Text], (_, a) =>
        {
            var target = (KrlPlace)a[0];
            target.Set(a[1] is string s ? s : KrlValues.Text((KrlArrayValue)a[1]));
            return true;
        }));
        Add(new("StrAdd", KrlType.Int, [new(KrlType.Array(KrlType.Char, 0), IsOut: true), KrlBuiltinParameter.Text], (_, a) => StrAdd((KrlPlace)a[0], Text(a[1]))));
        Add(new("StrLen", KrlType.Int, [KrlBuiltinParameter.Text], (_, a) => a[0] is string s ? s.Length : KrlValues.Text((KrlArrayValue)a[0]).Length));
        Add(new("Set_KrlMsg", KrlType.Int, [new(KrlType.Enum), new(KrlTypes.KrlMsg), new(KrlType.Array(KrlTypes.KrlMsgPar, 0)), new(KrlTypes.KrlMsgOpt)], Message));
        KrlBuiltinParameter optionalText = new(KrlType.Array(KrlType.Char, 0), Optional: true);
        KrlBuiltinParameter[] notify = [KrlBuiltinParameter.Text, optionalText, new(KrlType.Int, Optional: true), optionalText, optionalText, optionalText];
        Add(new("MsgNotify", null, notify, Notify));
        // The message library's variant with text parameters, as KUKA's own EthernetKRL server calls it (text, module, number, texts).
        Add(new("MsgNotifyTextPar", null, notify, Notify));
        // VarState(name): every variable the twin has holds a value (a declared one its type's default), so #INITIALIZED.
        Add(new("VarState", KrlType.Enum, [KrlBuiltinParameter.Text], (_, _) => new KrlEnumValue("INITIALIZED")));
        Add(Math1("ABS", Math.Abs));
        Add(Math1("SQRT", x => x < 0 ? throw new KrlRuntimeException("SQRT of a negative number") : Math.Sqrt(x)));
        Add(Math1("SIN", x => Math.Sin(x * Math.PI / 180)));
        Add(Math1("COS", x => Math.Cos(x * Math.PI / 180)));
        Add(Math1("TAN", x => Math.Tan(x * Math.PI / 180)));
        Add(Math1("ACOS", x => Math.Acos(x) * 180 / Math.PI));
        Add(new("EKI_GetFrameArray", KrlTypes.EkiStatus, [KrlBuiltinParameter.Text, KrlBuiltinParameter.Text, new(KrlType.Array(KrlTypes.Frame, 0), IsOut: true)],
            (machine, a) => machine.Controller.EkiGetFrameArray(Text(a[0]), Text(a[1]), (KrlPlace)a[2])));
        Add(new("ATAN2", KrlType.Real, [KrlBuiltinParameter.Real, KrlBuiltinParameter.Real],
            (_, a) => Math.Atan2(KrlValues.ToReal(a[0]), KrlValues.ToReal(a[1])) * 180 / Math.PI));
    }

    /// <summary>
    /// MsgNotify(text[], module[], number, par1[], par2[], par3[]) of KUKA's message library: a notification on the pendant,
    /// "NOTIFY module number: text" with %1 to %3 replaced by the parameters (any of the last five may be left out).
    /// </summary>
    private static object? Notify(KrlMachine machine, object[] a)
    {
        string Text(int i) => i < a.Length && a[i] is { } value ? (value is string s ? s : KrlValues.Text((KrlArrayValue)value)) : "";
        string text = Text(0);
        for (int i = 1; i <= 3; i++)
        {
            text = text.Replace("%" + i.ToString(System.Globalization.CultureInfo.InvariantCulture), Text(2 + i), StringComparison.Ordinal);
        }
        string number = a.Length > 2 && a[2] is int n ? " " + n.ToString(System.Globalization.CultureInfo.InvariantCulture) : "";
        machine.Controller.Pendant.Log($"NOTIFY {Text(1)}{number}: {text}".Replace("NOTIFY :", "NOTIFY:", StringComparison.Ordinal));
        return null;
    }

    /// <summary>
    /// StrAdd(dest[], add[]) of the KSS string functions: appends <paramref name="add"/> to the text of <paramref name="target"/>
    /// and returns the new length; 0, with the text unchanged, when the result would not fit the array.
    /// </summary>
    private static int StrAdd(KrlPlace target, string add)
    {
        var array = (KrlArrayValue)target.Get();
        string joined = KrlValues.Text(array) + add;
        if (joined.Length > array.Length)
        {
            return 0;
        }
        target.Set(joined);
        return joined.Length;
    }

    /// <summary>A text argument (a string literal or a CHAR array).</summary>
    private static string Text(object value) => value is string s ? s : KrlValues.Text((KrlArrayValue)value);

    private static KrlBuiltin Math1(string name, Func<double, double> f) =>
        new(name, KrlType.Real, [KrlBuiltinParameter.Real], (_, a) => f(KrlValues.ToReal(a[0])));

    /// <summary>INVERSE(position, start axes, status): the axis angles of a Cartesian position (in $BASE with $TOOL); status 0 when found.</summary>
    private static object? Inverse(KrlMachine machine, object[] a)
    {
        var status = (KrlPlace)a[2];
        // Arguments of the parameters' own types are only read (the driver's E6POS and E6AXIS): no copy of each per call.
        KrlStructValue start = a[1] is KrlStructValue { } axes && axes.Type == KrlTypes.E6Axis ? axes : (KrlStructValue)KrlConvert.To(KrlTypes.E6Axis, a[1], null);
        KrlStructValue position = a[0] is KrlStructValue { } pose && pose.Type == KrlTypes.E6Pos ? pose : (KrlStructValue)KrlConvert.To(KrlTypes.E6Pos, a[0], null);
        Joints near = KrlTwinController.JointsOf(start);
        Joints? solution = machine.Controller.Solve(position, near, useStatusTurn: false, out _);
        status.Set(solution is null ? 1 : 0);
        // The answer is the caller's own (ReturnsFresh): the start axes as a copy when they are the argument itself.
        return solution is { } j ? KrlTwinController.AxesValue(j) : ReferenceEquals(start, a[1]) ? start.Copy() : start;
    }

    private static object? Message(KrlMachine machine, object[] a)
    {
        var kind = (KrlEnumValue)a[0];
        var message = (KrlStructValue)KrlConvert.To(KrlTypes.KrlMsg, a[1], null);
        string module = KrlValues.Text((KrlArrayValue)message.Values[0]);
        string text = KrlValues.Text((KrlArrayValue)message.Values[2]).TrimEnd();
        machine.Controller.Pendant.Log(FormattableString.Invariant($"{kind.Name.ToUpperInvariant()} {module} {message.Values[1]}: {text}"));
        return machine.Controller.NextMessageHandle();
    }
}
