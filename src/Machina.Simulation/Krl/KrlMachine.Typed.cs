namespace Machina.Simulation.Krl;

/// <summary>
/// Typed evaluation: an INT, REAL or BOOL expression's value without a box for it or for any value under it. The binder fixed
/// each operation's type (<see cref="KrlExpr.Type"/>), so an operation of REALs adds two doubles where the walk boxed each
/// operand and each result, and a condition is a <see cref="bool"/> from its comparison down. The rules are KRL's (and the walk's
/// before): INT operations wrap in 32 bits, an INT meets a REAL as a REAL, a division by 0 stops the program, and both operands
/// of AND, OR and EXOR are evaluated, left first.
/// </summary>
internal sealed partial class KrlMachine
{
    /// <summary>The value of the number expression <paramref name="expr"/> as a REAL.</summary>
    private double RealOf(KrlExpr expr, object[] frame)
    {
        if (expr.Node == KrlNode.Member && expr.Type.Kind is KrlKind.Real or KrlKind.Int)
        {
            return RealComponent((KrlMember)expr, frame);
        }
        if (expr.Node == KrlNode.Index && expr.Type.Kind is KrlKind.Real or KrlKind.Int && ((KrlIndex)expr).Access == KrlAccess.Element)
        {
            return RealElement((KrlIndex)expr, frame);
        }
        if (expr.Node == KrlNode.Binary)
        {
            KrlKind kind = expr.Type.Kind;
            if (kind == KrlKind.Real)
            {
                return RealBinary((KrlBinary)expr, frame);
            }
            if (kind == KrlKind.Int)
            {
                return IntBinary((KrlBinary)expr, frame);
            }
        }
        return KrlValues.ToReal(Eval(expr, frame));
    }

    /// <summary>The value of the INT expression <paramref name="expr"/> (a REAL value is rounded, as KRL assigns REAL to INT).</summary>
    private int IntOf(KrlExpr expr, object[] frame)
    {
        if (expr.Node == KrlNode.Binary && expr.Type.Kind == KrlKind.Int)
        {
            return IntBinary((KrlBinary)expr, frame);
        }
        return KrlValues.ToInt(Eval(expr, frame));
    }

    /// <summary>The value of the BOOL expression <paramref name="expr"/>.</summary>
    private bool BoolOf(KrlExpr expr, object[] frame)
    {
        switch (expr.Node)
        {
            case KrlNode.Binary:
                return BoolBinary((KrlBinary)expr, frame);
            case KrlNode.Literal:
                return (bool)((KrlLiteral)expr).Value;
            default:
                return (bool)Eval(expr, frame);
        }
    }

    /// <summary>+ - * / of a REAL type (at least one operand a REAL).</summary>
    private double RealBinary(KrlBinary binary, object[] frame)
    {
        CheckStack();
        double x = RealOf(binary.Left, frame);
        double y = RealOf(binary.Right, frame);
        return binary.Code switch
        {
            0 => x + y,
            1 => x - y,
            2 => x * y,
            _ => y == 0 ? throw new KrlRuntimeException("Division by 0") : x / y,
        };
    }

    /// <summary>+ - * / B_AND B_OR B_EXOR of two INTs.</summary>
    private int IntBinary(KrlBinary binary, object[] frame)
    {
        CheckStack();
        int a = IntOf(binary.Left, frame);
        int b = IntOf(binary.Right, frame);
        return binary.Code switch
        {
            0 => a + b,
            1 => a - b,
            2 => a * b,
            3 => b == 0 ? throw new KrlRuntimeException("Division by 0")
                : a == int.MinValue && b == -1 ? throw new KrlRuntimeException("Arithmetic overflow: -2147483648 / -1 is not an INT")
                : a / b,
            7 => a & b,
            8 => a | b,
            _ => a ^ b,
        };
    }

    /// <summary>AND OR EXOR, and the comparisons == &lt;&gt; &lt; &lt;= &gt; &gt;=.</summary>
    private bool BoolBinary(KrlBinary binary, object[] frame)
    {
        CheckStack();
        int code = binary.Code;
        if (code is >= 4 and <= 6)
        {
            bool p = BoolOf(binary.Left, frame);
            bool q = BoolOf(binary.Right, frame);
            return code == 4 ? p && q : code == 5 ? p || q : p ^ q;
        }
        KrlKind left = binary.Left.Type.Kind, right = binary.Right.Type.Kind;
        if (left == KrlKind.Int && right == KrlKind.Int)
        {
            int a = IntOf(binary.Left, frame);
            int b = IntOf(binary.Right, frame);
            return code == 10 ? a == b : code == 11 ? a != b : Compare(code, a.CompareTo(b));
        }
        if (left is KrlKind.Int or KrlKind.Real && right is KrlKind.Int or KrlKind.Real)
        {
            double x = RealOf(binary.Left, frame);
            double y = RealOf(binary.Right, frame);
            return code == 10 ? x == y : code == 11 ? x != y : Compare(code, x.CompareTo(y));
        }
        if (left == KrlKind.Bool && right == KrlKind.Bool)
        {
            bool p = BoolOf(binary.Left, frame);
            bool q = BoolOf(binary.Right, frame);
            return code == 10 ? p == q : p != q;
        }
        object l = Eval(binary.Left, frame);
        object r = Eval(binary.Right, frame);
        return code switch
        {
            10 => Equal(l, r),
            11 => !Equal(l, r),
            _ => Compare(code, ((char)l).CompareTo((char)r)),
        };
    }
}
