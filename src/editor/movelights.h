// Reordering (drag and drop in the light table) as one undo step: any set of rows is moved to become one
// contiguous block, in its current order, before the light now at index destination (0..count). One block
// is moved as such (views get rowsMoved); several blocks are applied as one permutation (views get one layout
// change, not one signal per block).
#pragma once

#include "editor/rigcommand.h"

#include <memory>

namespace lr {

class MoveLights : public RigCommand {
  public:
    // nullptr and *error when rows are empty/out of range or destination is outside 0..lightCount(), or when
    // the move would change nothing (*error empty then).
    static std::unique_ptr<MoveLights> create(Document* document, const QList<int>& rows, int destination,
                                              QString* error = nullptr);
    void undo() override;
    void redo() override;

    struct BlockMove {
        int first, count, destination; // destination as in beginMoveRows (index before the move)
    };

  private:
    MoveLights(Document* document, QList<BlockMove> moves, int count);
    QList<BlockMove> m_moves;      // positions, not ids: a move is about where lights are
    QList<int> m_order, m_inverse; // permutation (several blocks only)
};

} // namespace lr
