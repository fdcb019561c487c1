namespace Machina.Simulation.Rapid;

/// <summary>
/// The FlexPendant's dialogs (TPReadFK, TPReadNum, TPReadDnum, UIMsgBox, UIMessageBox, UINumEntry, UIAlphaEntry). The twin has no
/// operator: each dialog answers at once with its default (the \DefaultBtn, \InitValue or \InitString, else the first button or key)
/// and says so on the pendant.
/// </summary>
internal static partial class RapidBuiltins
{
    private static RapidBuiltinParam[] Breaks() =>
        [Opt("MaxTime", "num"), Opt("DIBreak", "signaldi"), Sw("DIPassive"), Opt("DOBreak", "signaldo"), Sw("DOPassive"), Opt("BreakFlag", "errnum", true)];

    private static RapidBuiltinParam[] Dialog(params RapidBuiltinParam[] own) =>
        [Opt("Header", "string"), Opt("Message", "string"), new RapidBuiltinParam("MsgArray", "string", Optional: true, Rank: 1), Sw("Wrap"), Opt("Icon", "icondata"), Opt("Image", "string"),
            .. own, .. Breaks(), Opt("UIActiveSignal", "signaldo")];

    private static IEnumerable<RapidBuiltin> Pendant() =>
    [
        Instruction("TPReadFK", [P("TPAnswer", "num", true), P("TPText", "string"), P("TPFK1", "string"), P("TPFK2", "string"), P("TPFK3", "string"),
            P("TPFK4", "string"), P("TPFK5", "string"), .. Breaks()], call =>
        {
            int key = 1;
            while (key < 5 && call.Str(1 + key).Length == 0)
            {
                key++;
            }
            NoOperator(call, "TPReadFK", call.Str(1), $"function key {key} (\"{call.Str(1 + key)}\")");
            call.Set(0, (double)key);
        }),
        Instruction("TPReadNum", [P("TPAnswer", "num", true), P("TPText", "string"), .. Breaks()], call =>
        {
            NoOperator(call, "TPReadNum", call.Str(1), "0");
            call.Set(0, 0.0);
        }),
        Instruction("TPReadDnum", [P("TPAnswer", "dnum", true), P("TPText", "string"), .. Breaks()], call =>
        {
            NoOperator(call, "TPReadDnum", call.Str(1), "0");
            call.Set(0, 0.0);
        }),
        Instruction("UIMsgBox", [Opt("Header", "string"), P("MsgLine1", "string"), Opt("MsgLine2", "string"), Opt("MsgLine3", "string"),
            Opt("MsgLine4", "string"), Opt("MsgLine5", "string"), Sw("Wrap"), Opt("Buttons", "buttondata"), Opt("Icon", "icondata"), Opt("Image", "string"),
            Opt("Result", "btnres", true), .. Breaks(), Opt("UIActiveSignal", "signaldo")], call =>
        {
            double answer = FirstButton(call.Has(7) ? call.Num(7) : 0);
            NoOperator(call, "UIMsgBox", call.Str(1), Button(answer));
            if (call.Has(10))
            {
                call.Set(10, answer);
            }
        }),
        Function("UIMessageBox", "btnres", Dialog(Opt("Buttons", "buttondata"), new RapidBuiltinParam("BtnArray", "string", Optional: true, Rank: 1), Opt("DefaultBtn", "btnres")), call =>
        {
            double answer = call.Has(8) ? call.Num(8) : call.Has(7) ? 1 : FirstButton(call.Has(6) ? call.Num(6) : 0);
            NoOperator(call, "UIMessageBox", Text(call), call.Has(7) ? $"button {RapidValues.FormatNumber(answer)}" : Button(answer));
            return answer;
        }),
        Function("UINumEntry", "num", Dialog(Opt("InitValue", "num"), Opt("MinValue", "num"), Opt("MaxValue", "num"), Sw("AsInteger")), call =>
        {
            double answer = call.Has(6) ? call.Num(6) : call.Has(7) ? call.Num(7) : 0;
            NoOperator(call, "UINumEntry", Text(call), RapidValues.FormatNumber(answer));
            return answer;
        }),
        Function("UIAlphaEntry", "string", Dialog(Opt("InitString", "string")), call =>
        {
            string answer = call.Has(6) ? call.Str(6) : "";
            NoOperator(call, "UIAlphaEntry", Text(call), $"\"{answer}\"");
            return answer;
        }),
    ];

    /// <summary>The message of a UI function's dialog: \Message, else \Header.</summary>
    private static string Text(RapidCall call) => call.Has(1) ? call.Str(1) : call.Has(0) ? call.Str(0) : "";

    /// <summary>The result of the first button of a buttondata (btnOK, btnAbrtRtryIgn … btnYesNoCancel).</summary>
    private static double FirstButton(double buttons) => buttons switch
    {
        -1 => 0, // btnNone: BTN_NONE
        1 => 2, // btnAbrtRtryIgn: BTN_ABORT
        3 => 3, // btnRetryCancel: BTN_RETRY
        4 or 5 => 6, // btnYesNo, btnYesNoCancel: BTN_YES
        _ => 1, // btnOK, btnOKCancel: BTN_OK
    };

    private static string Button(double result) => result switch
    {
        1 => "BTN_OK",
        2 => "BTN_ABORT",
        3 => "BTN_RETRY",
        4 => "BTN_IGNORE",
        5 => "BTN_CANCEL",
        6 => "BTN_YES",
        7 => "BTN_NO",
        _ => "BTN_NONE",
    };

    /// <summary>Tells the pendant that a dialog found no operator and what it answered.</summary>
    private static void NoOperator(RapidCall call, string dialog, string text, string answer)
    {
        RapidTwinController c = call.Machine.Task.Controller;
        c.Pendant.Log($"{c.TaskLabel(call.Machine.Task)}{dialog} \"{text}\": no operator at the pendant, answered {answer} (line {call.Line})");
    }
}
