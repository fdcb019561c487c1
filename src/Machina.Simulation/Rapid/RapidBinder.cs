namespace Machina.Simulation.Rapid;

/// <summary>
/// Resolves the names of a task's modules and checks their types, as the controller does when it loads them: an unknown
/// name, a wrong type or a wrong argument refuses the module with its line. Module data get their initial values.
/// </summary>
internal sealed partial class RapidBinder
{
    private readonly RapidProgram _program;
    private readonly RapidMachine _machine;
    private readonly IReadOnlyDictionary<string, RapidBuiltin> _builtins;
    private readonly Dictionary<string, RapidCell> _persistents;
    private readonly Dictionary<RapidModule, Dictionary<string, RapidCell>> _localData = [];
    private readonly Dictionary<RapidModule, Dictionary<string, RapidRoutine>> _localRoutines = [];

    /// <summary>The array elements of the module data bound so far (bounded by <see cref="Twin.TwinLimits.MaxTotalElements"/>).</summary>
    private long _elements;
    private RapidModule _module = null!;

    private RapidBinder(RapidProgram program, RapidMachine machine, IReadOnlyDictionary<string, RapidBuiltin> builtins, Dictionary<string, RapidCell> persistents)
    {
        _program = program;
        _machine = machine;
        _builtins = builtins;
        _persistents = persistents;
    }

    /// <summary>
    /// Binds <paramref name="modules"/> into <paramref name="program"/> (which already holds the predefined data). PERS data are
    /// shared through <paramref name="persistents"/> (one table for every task of a controller).
    /// </summary>
    public static void Bind(RapidProgram program, RapidMachine machine, IReadOnlyList<RapidModule> modules,
        IReadOnlyDictionary<string, RapidBuiltin> builtins, Dictionary<string, RapidCell> persistents)
    {
        var binder = new RapidBinder(program, machine, builtins, persistents);
        try
        {
            foreach (RapidModule module in modules)
            {
                binder.Declare(module);
            }
            binder.InitializeData(modules);
            foreach (RapidModule module in modules)
            {
                binder._module = module;
                foreach (RapidRoutine routine in module.Routines)
                {
                    binder.BindRoutine(routine);
                }
            }
        }
        catch (RapidLoadException ex) when (ex.Module is null && binder._module is not null)
        {
            throw new RapidLoadException(ex.Line, ex.Reason) { Module = binder._module.Name };
        }
        program.Modules.AddRange(modules);
    }

    private static RapidLoadException Refuse(int line, string message) => new(line, message);

    private void Declare(RapidModule module)
    {
        _module = module;
        if (_program.Modules.Any(m => m.Name.Equals(module.Name, StringComparison.OrdinalIgnoreCase)))
        {
            throw Refuse(module.Line, RapidLoadException.Reference($"a module named '{module.Name}' is already loaded"));
        }
        foreach (RapidRecordDecl record in module.Records)
        {
            if (_program.Types.ContainsKey(record.Name))
            {
                throw Refuse(record.Line, RapidLoadException.Reference($"the type '{record.Name}' is already defined"));
            }
            var fields = new List<(string, RapidDataType)>();
            foreach ((string typeName, string name) in record.Fields)
            {
                fields.Add((name, new RapidDataType(TypeNamed(typeName, record.Line))));
            }
            _program.Types[record.Name] = new RapidType(record.Name, fields);
        }
        _localData[module] = new(StringComparer.OrdinalIgnoreCase);
        _localRoutines[module] = new(StringComparer.OrdinalIgnoreCase);
        foreach (RapidRoutine routine in module.Routines)
        {
            Dictionary<string, RapidRoutine> scope = routine.Local ? _localRoutines[module] : _program.Routines;
            if (scope.ContainsKey(routine.Name) || _builtins.ContainsKey(routine.Name))
            {
                throw Refuse(routine.Line, RapidLoadException.Reference($"the routine '{routine.Name}' is already defined"));
            }
            scope[routine.Name] = routine;
            if (routine.Kind == RapidRoutineKind.Func)
            {
                routine.ReturnType = new RapidDataType(TypeNamed(routine.ReturnTypeName!, routine.Line));
            }
        }
    }

    private RapidType TypeNamed(string name, int line) => _program.Types.TryGetValue(name, out RapidType? type)
        ? type
        : throw Refuse(line, RapidLoadException.Reference($"'{name}' is not a data type"));

    /// <summary>Declares one datum of the module being bound (<see cref="_module"/>) and gives it its initial value.</summary>
    private void InitializeDatum(RapidDataDecl decl)
    {
        Dictionary<string, RapidCell> local = _localData[_module];
        if (local.ContainsKey(decl.Name) || (!decl.Local && _program.Globals.TryGetValue(decl.Name, out RapidCell? old) && old.Storage != RapidStorage.Pers
            && !_program.Predefined.Remove(decl.Name))
            || _program.Routines.ContainsKey(decl.Name))
        {
            throw Refuse(decl.Line, RapidLoadException.Reference($"'{decl.Name}' is already defined"));
        }
        var type = new RapidDataType(TypeNamed(decl.TypeName, decl.Line), decl.Dimensions.Length);
        int[] dims = Dimensions(decl, null);
        if (dims.Length > 0 && (_elements += _machine.Limits.Elements(dims) ?? 0) > _machine.Limits.MaxTotalElements)
        {
            throw Refuse(decl.Line, RapidLoadException.Type($"the data of the modules hold more than {_machine.Limits.MaxTotalElements:N0} array elements (the twin's limit)"));
        }
        RapidCell cell;
        if (decl.Storage == RapidStorage.Pers && _persistents.TryGetValue(decl.Name, out RapidCell? shared))
        {
            if (!shared.Type.Accepts(type) || !type.Accepts(shared.Type))
            {
                throw Refuse(decl.Line, RapidLoadException.Type($"the persistent '{decl.Name}' is a {shared.Type} elsewhere, not a {type}"));
            }
            cell = shared;
        }
        else
        {
            cell = new RapidCell(decl.Name, type, decl.Storage, RapidValues.Default(type, dims));
            if (decl.Initial is not null)
            {
                BindValue(decl.Initial, type, new RapidScope(null));
                cell.Value = RapidValues.Copy(_machine.Evaluate(decl.Initial, null));
            }
            if (decl.Storage == RapidStorage.Pers)
            {
                _persistents[decl.Name] = cell;
            }
        }
        (decl.Local ? local : _program.Globals)[decl.Name] = cell;
        if (decl.Local)
        {
            _program.ModuleData.TryAdd(decl.Name, cell);
        }
    }

    /// <summary>The sizes of an array declaration: constant expressions.</summary>
    private int[] Dimensions(RapidDataDecl decl, RapidScope? scope)
    {
        var dims = new int[decl.Dimensions.Length];
        for (int i = 0; i < dims.Length; i++)
        {
            BindValue(decl.Dimensions[i], new RapidDataType(RapidTypes.Num), scope ?? new RapidScope(null));
            double size = (double)_machine.Evaluate(decl.Dimensions[i], null);
            if (size < 1 || size != Math.Floor(size))
            {
                throw Refuse(decl.Line, RapidLoadException.Type($"the size of '{decl.Name}' must be a positive integer, not {RapidValues.FormatNumber(size)}"));
            }
            dims[i] = size <= int.MaxValue ? (int)size : int.MaxValue;
        }
        if (_machine.Limits.Elements(dims) is null)
        {
            throw Refuse(decl.Line, RapidLoadException.Type($"'{decl.Name}': {_machine.Limits.ArrayTooLarge(dims)}"));
        }
        return dims;
    }

    private RapidCell? GlobalData(string name) =>
        _localData.TryGetValue(_module, out Dictionary<string, RapidCell>? local) && local.TryGetValue(name, out RapidCell? cell) ? cell
        : _program.Globals.GetValueOrDefault(name);

    private RapidRoutine? RoutineNamed(string name) =>
        _localRoutines.TryGetValue(_module, out Dictionary<string, RapidRoutine>? local) && local.TryGetValue(name, out RapidRoutine? r) ? r
        : _program.Routines.GetValueOrDefault(name);
}

/// <summary>The local names of a routine being bound: parameters, local data and loop variables, each with its frame slot.</summary>
internal sealed class RapidScope(RapidRoutine? routine)
{
    private readonly List<Dictionary<string, (int Slot, bool ReadOnly)>> _levels = [new(StringComparer.OrdinalIgnoreCase)];

    /// <summary>The routine (null for module data).</summary>
    public RapidRoutine? Routine { get; } = routine;

    /// <summary>True while binding the ERROR handler.</summary>
    public bool InErrorHandler { get; set; }

    /// <summary>The labels of the routine.</summary>
    public HashSet<string> Labels { get; } = new(StringComparer.OrdinalIgnoreCase);

    /// <summary>Adds a local; returns its slot.</summary>
    public int Add(string name, RapidDataType type, bool readOnly)
    {
        int slot = Routine!.SlotTypes.Count;
        Routine.SlotTypes.Add(type);
        _levels[^1][name] = (slot, readOnly);
        return slot;
    }

    /// <summary>True when <paramref name="name"/> is declared at the innermost level already.</summary>
    public bool DeclaredHere(string name) => _levels[^1].ContainsKey(name);

    /// <summary>The slot of a local, or null.</summary>
    public (int Slot, bool ReadOnly)? Find(string name)
    {
        for (int i = _levels.Count - 1; i >= 0; i--)
        {
            if (_levels[i].TryGetValue(name, out (int, bool) found))
            {
                return found;
            }
        }
        return null;
    }

    /// <summary>Opens a nested level (a FOR loop's variable).</summary>
    public void Push() => _levels.Add(new(StringComparer.OrdinalIgnoreCase));

    /// <summary>Closes the innermost level.</summary>
    public void Pop() => _levels.RemoveAt(_levels.Count - 1);
}
