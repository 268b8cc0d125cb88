// placeholder until implemented in this session
