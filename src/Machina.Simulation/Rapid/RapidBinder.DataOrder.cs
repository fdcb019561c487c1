namespace Machina.Simulation.Rapid;

/// <summary>
/// The order in which module data get their values: a declaration may name data that a later module (or a later line) declares,
/// as a controller links a task's modules together before it runs them (e.g. an array sized by a CONST of another module).
/// </summary>
internal sealed partial class RapidBinder
{
    /// <summary>The module data not declared yet, by name, with their modules (null when no order is being worked out).</summary>
    private Dictionary<string, List<RapidModule>>? _pending;

    /// <summary>Thrown while a declaration names data still to come: the declaration waits for it.</summary>
    private sealed class WaitsForData : Exception;

    /// <summary>
    /// Declares the data of every module, each after the data its sizes and initial value name: declarations are taken in
    /// their order and one that names data still to come waits; what still waits when nothing more can be declared (data that
    /// name each other) is refused with the reference error of the first.
    /// </summary>
    private void InitializeData(IReadOnlyList<RapidModule> modules)
    {
        _pending = new(StringComparer.OrdinalIgnoreCase);
        var waiting = new List<(RapidModule Module, RapidDataDecl Decl)>();
        foreach (RapidModule module in modules)
        {
            foreach (RapidDataDecl decl in module.Data)
            {
                waiting.Add((module, decl));
                (_pending.TryGetValue(decl.Name, out List<RapidModule>? owners) ? owners : _pending[decl.Name] = []).Add(module);
            }
        }
        while (waiting.Count > 0)
        {
            int before = waiting.Count;
            waiting.RemoveAll(TryInitialize);
            if (waiting.Count == before)
            {
                _pending = null; // no more progress: the first one left is refused with its own reference error
                (_module, RapidDataDecl first) = waiting[0];
                InitializeDatum(first);
            }
        }
        _pending = null;
    }

    /// <summary>Declares one datum unless it names data still to come; true when it was declared.</summary>
    private bool TryInitialize((RapidModule Module, RapidDataDecl Decl) item)
    {
        _module = item.Module;
        if (_pending is not null && NamesDataToCome(item.Decl))
        {
            return false;
        }
        InitializeDatum(item.Decl);
        List<RapidModule> owners = _pending![item.Decl.Name];
        owners.Remove(item.Module);
        if (owners.Count == 0)
        {
            _pending.Remove(item.Decl.Name);
        }
        return true;
    }

    /// <summary>True when the sizes or the initial value of <paramref name="decl"/> name data still to come.</summary>
    private bool NamesDataToCome(RapidDataDecl decl)
    {
        try
        {
            foreach (RapidExpr size in decl.Dimensions)
            {
                BindValue(size, new RapidDataType(RapidTypes.Num), new RapidScope(null));
            }
            if (decl.Initial is not null)
            {
                BindValue(decl.Initial, new RapidDataType(TypeNamed(decl.TypeName, decl.Line), decl.Dimensions.Length), new RapidScope(null));
            }
            return false;
        }
        catch (WaitsForData)
        {
            return true;
        }
        catch (RapidLoadException)
        {
            return false; // declaring it reports this error
        }
    }

    /// <summary>True when <paramref name="name"/> is module data still to come (of any module: one it cannot see is refused once declared).</summary>
    private bool IsDataToCome(string name) =>
        _pending is not null && _pending.TryGetValue(name, out List<RapidModule>? owners) && owners.Count > 0;
}
