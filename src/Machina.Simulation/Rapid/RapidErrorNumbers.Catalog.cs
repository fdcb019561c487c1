namespace Machina.Simulation.Rapid;

/// <summary>
/// The rest of RAPID's predefined error numbers (the "errnum" data type of the Instructions, Functions and Data types reference):
/// programs written for a controller name them in error handlers and error lists, whether or not the twin ever raises them.
/// </summary>
internal static partial class RapidErrorNumbers
{
    /// <summary>GetDataVal/SetDataVal: no data of that name is reachable, or it may not be read or written.</summary>
    public const int SymAccess = 41014;

    /// <summary>GetDataVal/SetDataVal: the data found is not of the type of the argument.</summary>
    public const int SymbolType = 41015;

    /// <summary>RETRY ran more times than the controller allows for one error (the twin's limit).</summary>
    public const int RetryMax = 41016;

    /// <summary>LONG_JMP_ALL_ERR: in an error list, every error (a handler for the errors a trap raises, RAPID's long jump).</summary>
    public const int LongJumpAll = 41099;

    /// <summary>The first number the catalog below hands out.</summary>
    private const int CatalogStart = 41100;

    // The names RAPID defines besides the ones the twin raises (above and in RapidErrorNumbers.cs). Each gets a number of its own.
    private static readonly string[] Catalog =
    [
        "ERR_ACC_TOO_LOW", "ERR_ALRDYCNT", "ERR_ALRDY_MOVING", "ERR_AO_LIM", "ERR_ARGDUPCND", "ERR_ARGNAME", "ERR_ARGNOTPER", "ERR_ARRAY_SIZE",
        "ERR_AXIS_ACT", "ERR_AXIS_IND", "ERR_AXIS_MOVING", "ERR_AXIS_PAR", "ERR_BUSSTATE", "ERR_BWDLIMIT", "ERR_CALLIO_INTER", "ERR_CALLPROC",
        "ERR_CFG_INTERNAL", "ERR_CFG_ILL_DOMAIN", "ERR_CFG_ILLTYPE", "ERR_CFG_LIMIT", "ERR_CFG_NOTFND", "ERR_CFG_OUTOFBOUNDS", "ERR_CFG_WRITEFILE",
        "ERR_CNTNOTVAR", "ERR_CNV_NOT_ACT", "ERR_CNV_CONNECT", "ERR_CNV_DROPPED", "ERR_COLL_STOP", "ERR_COMM_EXT", "ERR_COMM_INIT",
        "ERR_COMM_INIT_FAILED", "ERR_CONC_MAX", "ERR_CSV_INDEX", "ERR_DATA_RECV", "ERR_DEV_MAXTIME", "ERR_DIPLAG_LIM", "ERR_DIRNOTFND", "ERR_DIRNOTEMPTY",
        "ERR_DIRNOTDIR", "ERR_EXECPHR", "ERR_FILEACC", "ERR_FILEEXIST", "ERR_FILEOPEN", "ERR_FILNOTFND", "ERR_FNCNORET", "ERR_FRAME", "ERR_GO_LIM",
        "ERR_HAND_FAILEDGRIPPOS", "ERR_HAND_FAILEDMOVEPOS", "ERR_HAND_FAILEDVACUUM", "ERR_HAND_NOTCALIBRATED", "ERR_HAND_WRONGSTATE",
        "ERR_ILLDIM", "ERR_ILLQUAT", "ERR_ILLRAISE", "ERR_INDCNV_ORDER", "ERR_INOISSAFE", "ERR_INOMAX", "ERR_INT_NOTVAL", "ERR_INT_MAXVAL",
        "ERR_INVDIM", "ERR_IODISABLE", "ERR_IODN_TIMEOUT", "ERR_IOENABLE", "ERR_IOERROR", "ERR_LINKREF", "ERR_LOADED", "ERR_LOADID_FATAL",
        "ERR_LOADID_RETRY", "ERR_LOADNO_INUSE", "ERR_LOADNO_NOUSE", "ERR_MAXINTVAL", "ERR_MODULE", "ERR_MOD_NOT_LOADED", "ERR_MOD_NOTLOADED",
        "ERR_MSG_PENDING", "ERR_MT_ABORT", "ERR_MT_HOME", "ERR_MT_HOMERUN", "ERR_NAME_INVALID", "ERR_NO_SGUN", "ERR_NORUNUNIT", "ERR_NOTARR",
        "ERR_NOTEQDIM", "ERR_NOTINTVAL", "ERR_NOTSAVED", "ERR_NOT_MOVETASK", "ERR_NUM_LIMIT", "ERR_OVERFLOW", "ERR_PATH", "ERR_PATHDIST",
        "ERR_PATH_STOP", "ERR_PERSSUPSEARCH", "ERR_PID_MOVESTOP", "ERR_PID_RAISE_PP", "ERR_PRGMEMFULL", "ERR_PROCSIGNAL_OFF", "ERR_PROGSTOP",
        "ERR_RANYBIN_CHK", "ERR_RANYBIN_EOF", "ERR_RCVDATA", "ERR_REFUNKDAT", "ERR_REFUNKFUN", "ERR_REFUNKPRC", "ERR_REFUNKTRP", "ERR_RMQ_DIM",
        "ERR_RMQ_FULL", "ERR_RMQ_INVALID", "ERR_RMQ_INVMSG", "ERR_RMQ_MSGSIZE", "ERR_RMQ_NAME", "ERR_RMQ_NOMSG", "ERR_RMQ_TIMEOUT", "ERR_RMQ_VALUE",
        "ERR_SC_WRITE", "ERR_SGUN_ESTOP", "ERR_SGUN_MOTOFF", "ERR_SGUN_NEGVAL", "ERR_SGUN_NOTACT", "ERR_SGUN_NOTINIT", "ERR_SGUN_NOTOPEN",
        "ERR_SGUN_NOTSYNC", "ERR_SIGSUPSEARCH", "ERR_SIG_NOT_VALID", "ERR_SIG_NAME", "ERR_SOCK_NET_UNREACH", "ERR_SOCK_UNSPEC",
        "ERR_SPEEDLIM_VALUE", "ERR_SPEED_REFRESH_LIM", "ERR_STARTMOVE", "ERR_STORE_PROF", "ERR_SYNCMOVEOFF", "ERR_SYNCMOVEON", "ERR_SYNTAX",
        "ERR_TASKNAME", "ERR_TP_DIBREAK", "ERR_TP_DOBREAK", "ERR_TP_MAXTIME", "ERR_TP_NO_CLIENT", "ERR_TRUSTLEVEL", "ERR_TXTNOEXIST",
        "ERR_UDPUC_COMM", "ERR_UISHOW_FATAL", "ERR_UISHOW_FULL", "ERR_UNIT_PAR", "ERR_UNKINO", "ERR_UNKPROC", "ERR_UNLOAD", "ERR_USE_PROF",
        "ERR_WAITSYNCTASK", "ERR_WHLSEARCH", "ERR_WOBJ_MOVING", "ERR_INVALID_ADDRESS", "ERR_OUTSIDE_REACH",
    ];

    /// <summary><paramref name="core"/> with the twin's other numbers and the catalog's names (a name already there keeps its number).</summary>
    private static Dictionary<string, int> WithCatalog(Dictionary<string, int> core)
    {
        core["ERR_SYM_ACCESS"] = SymAccess;
        core["ERR_SYMBOL_TYPE"] = SymbolType;
        core["ERR_EXCRTYMAX"] = RetryMax;
        core["LONG_JMP_ALL_ERR"] = LongJumpAll;
        int next = CatalogStart;
        foreach (string name in Catalog)
        {
            core.TryAdd(name, next++);
        }
        return core;
    }
}
