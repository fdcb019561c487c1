// .NET 8 has no System.Threading.Lock: there the simulator's gates are plain objects, used with the same lock statements.
#if !NET9_0_OR_GREATER
global using Lock = System.Object;
#endif
