namespace Machina.Simulation.Krl;

/// <summary>Loading a data list's element initialisers (<c>NAME[i] = value</c> after the array's DECL).</summary>
internal sealed partial class KrlTwinController
{
    private void InitialiseElements(KrlDataList list, KrlModule module, KrlBinder binder)
    {
        foreach (KrlElementInitialiser element in list.Elements)
        {
            if (!module.Data.TryGetValue(element.Name, out KrlCell? cell) || cell.Type.Kind != KrlKind.Array)
            {
                throw new KrlLoadException(list.File, element.Line, $"{element.Name} is not an array declared in the data list");
            }
            IReadOnlyList<int> sizes = cell.Type.Sizes;
            if (element.Indices.Length == 0)
            {
                if (cell.Type.Element!.Kind != KrlKind.Char || sizes.Count != 1 || element.Value is not KrlLiteral { Value: string text })
                {
                    throw new KrlLoadException(list.File, element.Line, $"{element.Name}[] = takes a string, for a CHAR array");
                }
                binder.BindConstant(list.File, element.Value, cell.Type);
                cell.Value = KrlConvert.To(cell.Type, text, cell.Value);
                continue;
            }
            if (element.Indices.Length != sizes.Count)
            {
                throw new KrlLoadException(list.File, element.Line, $"{element.Name} has {sizes.Count} dimension(s), not {element.Indices.Length}");
            }
            int flat = 0;
            for (int d = 0; d < sizes.Count; d++)
            {
                if (element.Indices[d] < 1 || element.Indices[d] > sizes[d])
                {
                    throw new KrlLoadException(list.File, element.Line, $"index {element.Indices[d]} of {element.Name} is outside 1 to {sizes[d]}");
                }
                flat = flat * sizes[d] + element.Indices[d] - 1;
            }
            KrlType type = cell.Type.Element!;
            binder.BindConstant(list.File, element.Value, type);
            var items = (KrlArrayValue)cell.Value;
            items[flat] = KrlConvert.To(type, new KrlMachine(this, default).Eval(element.Value, []), items[flat]);
        }
    }
}
